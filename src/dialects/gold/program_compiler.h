// Compiles a whole Gold program one function at a time, so that memory stays flat however long
// the file: each body is checked and generated as soon as it is parsed, then its nodes are freed.
#pragma once
#include "bytecode/image.h"
#include "dialects/gold/lexer.h"
#include "dialects/gold/reporter.h"

namespace uprog::gold {

// The image (empty when there are errors). `keep_code` false (a check) keeps only the code's size:
// no image, no line table, but every diagnostic a build gives.
bytecode::Image compile_program(Lexer& lexer, Reporter& reporter, const Locator& locator,
                                bool keep_code);

}  // namespace uprog::gold
