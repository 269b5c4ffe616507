// Gold code generation: a checked program (or command line) into a bytecode::Image — typed
// int/float/pair opcodes by the manual's number rules, an EOL after every source line, the
// line table, globals and locals by name and type, routines and auto-routine events.
#pragma once
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "dialects/gold/ast.h"
#include "dialects/gold/checker.h"
#include "dialects/gold/reporter.h"

namespace uprog::gold {

// `with_lines` false leaves the line table empty: for a check, which needs only the diagnostics
// (the code is still generated, since its size can be an error, 65).
bytecode::Image generate_program(const Program& program, const Symbols& symbols,
                                 const Locator& locator, Reporter& reporter, bool with_lines = true);

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
