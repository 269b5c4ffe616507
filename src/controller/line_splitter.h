// Splits what a host sends into the Gold interpreter's expressions (manual 1.1): they end at
// ';', CR or LF; "**" comments to the end of the line; blank expressions are dropped.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace uprog::controller {

constexpr size_t kMaxExpressionChars = 511;  // manual 1.1

std::vector<std::string> split_expressions(std::string_view text);

}  // namespace uprog::controller
