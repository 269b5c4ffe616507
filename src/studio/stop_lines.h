// The host lines that stop a dialect's program from its command line (the studio's Stop button):
// the drive's own vocabulary, so that a debugger and the program's state see what a terminal's
// stop does. Sources in docs/studio.md, "Stop".
#pragma once
#include <string>
#include <vector>

#include "dialect/firmware.h"

namespace uprog::studio {

// Empty when the studio knows no stop line for the dialect.
std::vector<std::string> stop_lines(std::string_view dialect_name,
                                    const std::vector<dialect::ThreadInfo>& threads);

}  // namespace uprog::studio
