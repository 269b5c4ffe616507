// PUP's reference for editors (dialect/reference.h): the AG300 keywords (keywords.def, with
// akribis-drive.md's meanings), PUP's statements, math functions and directives.
#pragma once
#include <vector>

#include "dialect/reference.h"

namespace uprog::pup {

std::vector<dialect::ReferenceEntry> reference();

}  // namespace uprog::pup
