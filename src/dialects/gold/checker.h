// The Gold checker: resolves every name (locals, globals, functions, built-ins, drive commands,
// labels), gives every expression its kind, and reports the manual's semantic errors.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
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

// An error kept aside while a body is checked speculatively.
struct CapturedError {
  Error code;
  uint32_t offset;
  std::string_view name;  // what it is about (a view into the lexer's text), or empty
};

// What checking one function body found, kept until the driver knows whether it still holds.
struct CheckedBody {
  bool checked = false;  // false when the body is not checked at all (refused, a second body)
  int symbol = -1;
  std::vector<CapturedError> errors;
  std::vector<LabelSym> labels;            // its local labels
  std::vector<std::string_view> poisoned;  // undefined loop variables it reported
};

// A short fingerprint of a name (FNV-1a). Two names may share one: then a body is checked
// again for nothing, never kept wrongly.
inline uint32_t name_hash(std::string_view name) {
  uint32_t h = 2166136261u;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return h;
}

namespace detail {
class Checker;
}

// The checker of a whole program, in the order the streaming driver (program_compiler.h) uses
// it: speculate() on each body as it is parsed, then declare() everything, then for each body
// accept() its speculation or check_body() it again, then check_top().
class ProgramChecker {
 public:
  explicit ProgramChecker(Reporter& reporter);
  ~ProgramChecker();
  // Checks `body` against the declarations of `p` parsed so far; errors and effects go to `out`,
  // and every name whose meaning a later declaration could change to `queried` (as name_hash).
  void speculate(Program& p, FunctionDef& f, Block& body, CheckedBody& out,
                 std::vector<uint32_t>& queried);
  // Declares every global, function and top-level label of `p`, reporting their errors.
  void declare(Program& p);
  // The symbol whose body `f` is, or -1 when `f`'s body is not checked.
  int symbol_for_body(const FunctionDef& f) const;
  void accept(int symbol, CheckedBody& spec);
  void check_body(FunctionDef& f, int symbol, Block& body);
  void check_top(Program& p);
  void forget_locals(int symbol);
  Symbols& symbols();

 private:
  std::unique_ptr<detail::Checker> c_;
};
// Command-line statements, seeing `known` as globals (indices in that order).
void check_line(Block& block, const std::vector<KnownGlobal>& known, Reporter& reporter);

// The kind of `a op b` and of `op a` by the manual's rules (1.5, 1.6).
Kind binary_kind(Tok op, Kind a, Kind b);
Kind unary_kind(Tok op, Kind a);

}  // namespace uprog::gold
