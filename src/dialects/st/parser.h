// The ST parser: declarations (resolved in source order: a name is declared before its use),
// the seven programs, FUNCTIONs, statements and expressions with the page's precedence. The
// checks that need the whole file (calls, recursion, placement, labels) are the checker's.
#pragma once
#include <vector>

#include "dialects/st/ast.h"
#include "dialects/st/reporter.h"
#include "dialects/st/token.h"

namespace uprog::st {

Program parse(const std::vector<Token>& tokens, Reporter& reporter);

}  // namespace uprog::st
