// The ST lexer: `//` and `(* *)` comments, names, decimal, 16# and 2# numbers, strings in
// '…' with \n \t \\ \' escapes, operators. Errors 2, 3, 4 and 31 (floats, brackets) are its.
#pragma once
#include <string>
#include <vector>

#include "dialects/st/reporter.h"
#include "dialects/st/token.h"

namespace uprog::st {

// Every token of `text`, the last one End.
std::vector<Token> lex(const std::string& text, Reporter& reporter);

}  // namespace uprog::st
