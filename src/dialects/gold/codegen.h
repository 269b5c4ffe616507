// Gold code generation: a checked program (or command line) into a bytecode::Image — typed
// int/float/pair opcodes by the manual's number rules, an EOL after every source line, the
// line table, globals and locals by name and type, routines and auto-routine events.
#pragma once
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "bytecode/image.h"
#include "dialects/gold/ast.h"
#include "dialects/gold/checker.h"
#include "dialects/gold/reporter.h"

namespace uprog::gold {

// The constants of a program, shared by the generators of its parts.
struct ConstantTable {
  std::vector<bytecode::Constant> constants;
  std::unordered_map<uint64_t, uint32_t> index;  // (type << 32 | bits) -> constant
};

// A CALL or RESET whose routine number is filled in when the program is put together.
struct RoutineFixup {
  uint32_t pc;
  std::string_view name;  // the function's or label's
};

// One function's code, generated as soon as it is checked: addresses count from its first word.
struct FunctionCode {
  std::vector<uint32_t> code;
  std::vector<bytecode::LineEntry> lines;
  std::vector<bytecode::Local> locals;  // its locals, then its temporaries
  std::vector<RoutineFixup> fixups;
  bool ok = true;  // every label bound
};

// The body of function `symbol` (its locals already in `symbols`) into `out`, whose buffers
// are reused.
void generate_function(const Symbols& symbols, int symbol, const Block& body, uint32_t end_offset,
                       const Locator& locator, ConstantTable& constants, bool with_lines,
                       FunctionCode& out);

// The top level, then the functions' code in order (`bodies` per function symbol, null when
// not kept), the routines and the events. `body_words` and `bodies_ok` tell of the code that was
// generated but not kept (a check keeps none): the size limit (65) counts it. `check_only`
// gives no image, only the diagnostics.
bytecode::Image generate_program(const Program& program, const Symbols& symbols,
                                 const std::vector<const FunctionCode*>& bodies,
                                 uint32_t body_words, bool bodies_ok, const Locator& locator,
                                 Reporter& reporter, ConstantTable& constants,
                                 bool check_only = false);

// One value a command line shows: the global holding it and, for a pair, the one holding its
// run-time type (0 int, 1 float).
struct LineValue {
  Kind kind = Kind::Int;
  uint32_t value_global = 0;
  int32_t tag_global = -1;  // -1 unless kind is Dynamic
};

// The line runs as routine 0 ("$line"). Globals [0, known.size()) are the program's, in the
// same order; the shown values live in globals after them.
bytecode::Image generate_line(const Block& block, const std::vector<KnownGlobal>& known,
                              const Locator& locator, Reporter& reporter,
                              std::vector<LineValue>& values);

}  // namespace uprog::gold
