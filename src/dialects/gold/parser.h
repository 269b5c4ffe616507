// Gold parser: tokens to a syntax tree, with recovery (an error skips to the end of its line)
// and the manual's structural errors (nesting, misplaced break/continue/return, labels).
#pragma once
#include <vector>

#include "dialects/gold/ast.h"
#include "dialects/gold/lexer.h"
#include "dialects/gold/reporter.h"
#include "dialects/gold/token.h"

namespace uprog::gold {

// The nodes live in `arena`, which must outlive the returned tree. With `on_body`, function
// bodies go to it one by one instead (their nodes in its scratch arena).
Program parse_program(Lexer& lexer, Reporter& reporter, AstArena& arena,
                      FunctionBodySink* on_body = nullptr);

// The body of `f` (a function of the program `lexer` reads) parsed again, into `arena`.
Block reparse_body(Lexer& lexer, Reporter& reporter, AstArena& arena, const FunctionDef& f);

// A command-line line: statements only, as if inside a label routine (no functions, no labels).
Block parse_line(Lexer& lexer, Reporter& reporter, AstArena& arena);

}  // namespace uprog::gold
