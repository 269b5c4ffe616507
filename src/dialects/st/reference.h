// ST's reference for editors (dialect/reference.h): the S300's ASCII parameters and commands
// (ascii_table.h, with s300-drive.md's and docs/dialects/st.md's meanings), the keywords,
// built-ins and program names of the macro language.
#pragma once
#include <vector>

#include "dialect/reference.h"

namespace uprog::st {

std::vector<dialect::ReferenceEntry> reference();

}  // namespace uprog::st
