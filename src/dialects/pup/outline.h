// PUP's declarations for editors (dialect/outline.h): tasks (AProgTask[n]) and functions
// (AProgFunc[n], called with AProgFuncCall, n), #definevar'd variables and #define'd names
// (shared/spec/akribis-drive.md, PUP).
#pragma once
#include <string_view>
#include <vector>

#include "dialect/outline.h"

namespace uprog::pup {

std::vector<dialect::SourceSymbol> outline(std::string_view text);

}  // namespace uprog::pup
