// Gold's reference for editors (dialect/reference.h): the drive commands from the command table
// (commands.h), the keywords of manual 2.3, the built-in functions of manual 1.7, 1.12 and 1.13,
// and the auto-routine names.
#pragma once
#include <vector>

#include "dialect/reference.h"

namespace uprog::gold {

std::vector<dialect::ReferenceEntry> reference();

}  // namespace uprog::gold
