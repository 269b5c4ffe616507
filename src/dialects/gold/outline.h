// Gold's declarations for editors (dialect/outline.h): functions with their inputs and outputs
// (manual 2.5), int and float variables, global or local to a function (2.6), labels (##NAME,
// #@NAME, 2.11.2) and #define'd names (2.9.1).
#pragma once
#include <string_view>
#include <vector>

#include "dialect/outline.h"

namespace uprog::gold {

dialect::WordSyntax word_syntax();
std::vector<dialect::SourceSymbol> outline(std::string_view text);

}  // namespace uprog::gold
