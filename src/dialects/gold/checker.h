// The Gold checker: resolves every name (locals, globals, functions, built-ins, drive commands,
// labels), gives every expression its kind, and reports the manual's semantic errors.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dialects/gold/ast.h"
#include "dialects/gold/reporter.h"

namespace uprog::gold {

struct GlobalSym {
  std::string name;
  VarType type = VarType::Int;
  int32_t length = 0;  // 0 for a scalar
  uint32_t offset = 0;
};

struct LocalSym {
  std::string name;
  VarType type = VarType::Int;
};

struct LabelSym {
  std::string name;
  bool is_auto = false;
  int function = -1;  // the function holding a local label, -1 for the top level
  uint32_t offset = 0;
};

struct FunctionSym {
  std::string name;
  const FunctionDef* def = nullptr;  // the definition with a body, or the prototype
  bool has_body = false;
  bool is_auto = false;
  size_t inputs = 0, outputs = 0;
  std::vector<LocalSym> locals;  // inputs, outputs, then declared locals
};

struct Symbols {
  std::vector<GlobalSym> globals;
  std::vector<FunctionSym> functions;
  std::vector<LabelSym> labels;
};

// A variable the command line may use: a global of the loaded program.
struct KnownGlobal {
  std::string name;
  VarType type = VarType::Int;
  int32_t length = 0;
};

Symbols check_program(Program& program, Reporter& reporter);
// Command-line statements, seeing `known` as globals (indices in that order).
void check_line(Block& block, const std::vector<KnownGlobal>& known, Reporter& reporter);

// The kind of `a op b` and of `op a` by the manual's rules (1.5, 1.6).
Kind binary_kind(Tok op, Kind a, Kind b);
Kind unary_kind(Tok op, Kind a);

}  // namespace uprog::gold
