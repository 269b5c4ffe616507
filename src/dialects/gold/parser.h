// Gold parser: tokens to a syntax tree, with recovery (an error skips to the end of its line)
// and the manual's structural errors (nesting, misplaced break/continue/return, labels).
#pragma once
#include <vector>

#include "dialects/gold/ast.h"
#include "dialects/gold/reporter.h"
#include "dialects/gold/token.h"

namespace uprog::gold {

// The nodes live in `arena`, which must outlive the returned tree.
Program parse_program(const std::vector<Token>& tokens, Reporter& reporter, AstArena& arena);

// A command-line line: statements only, as if inside a label routine (no functions, no labels).
Block parse_line(const std::vector<Token>& tokens, Reporter& reporter, AstArena& arena);

}  // namespace uprog::gold
