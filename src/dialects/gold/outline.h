// Gold's declarations for editors (dialect/outline.h): functions with their inputs and outputs
// (manual 2.5), int and float variables, global or local to a function (2.6), labels (##NAME,
// #@NAME, 2.11.2) and #define'd names (2.9.1).
#pragma once
#include <optional>
#include <string_view>
#include <vector>

#include "dialect/outline.h"

namespace uprog::gold {

dialect::WordSyntax word_syntax();
// Over the source's words, whether it compiles or not.
std::vector<dialect::SourceSymbol> outline(std::string_view text);
// From the compiler's front end (preprocessor, lexer, parser; compiled_outline.cpp), #define'd
// names from outline(); nullopt when the front end refuses the source.
std::optional<std::vector<dialect::SourceSymbol>> compiled_outline(std::string_view text);

}  // namespace uprog::gold
