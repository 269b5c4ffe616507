// ST's declarations for editors (dialect/outline.h): BYTE/WORD/LONG/DLONG globals, programs
// (PROGRAM ... END_PROGRAM) and functions (FUNCTION ... END_FUNCTION), labels (L: at a line's
// start) and #DEFINE'd names (shared/spec/s300-drive.md, Program layout).
#pragma once
#include <string_view>
#include <vector>

#include "dialect/outline.h"

namespace uprog::st {

dialect::WordSyntax word_syntax();
std::vector<dialect::SourceSymbol> outline(std::string_view text);

}  // namespace uprog::st
