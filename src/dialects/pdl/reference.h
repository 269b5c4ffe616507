// PDL's reference for editors (dialect/reference.h): the drive's system variables and states
// (system_names.def, states.def, with pdl-drive.md's meanings), the commands and built-in
// functions of the manual's chapter 2 and its directives.
#pragma once
#include <vector>

#include "dialect/reference.h"

namespace uprog::pdl {

std::vector<dialect::ReferenceEntry> reference();

}  // namespace uprog::pdl
