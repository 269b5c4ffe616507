// PDL's declarations for editors (dialect/outline.h): #long/#short/#float globals (manual
// 2.5.2), procedures with their parameters and locals (1.4), tasks (#task/n, 2.5.1), labels
// (name:, 2.2.3) and #define'd names (2.5.3).
#pragma once
#include <string_view>
#include <vector>

#include "dialect/outline.h"

namespace uprog::pdl {

std::vector<dialect::SourceSymbol> outline(std::string_view text);

}  // namespace uprog::pdl
