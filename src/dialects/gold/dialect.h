// Gold as a dialect of the drive (dialect::Dialect): the compiler, the error tables, the firmware
// and the host's download lines. The registry (src/dialects/registry.cpp) lists it.
#pragma once
#include "dialect/dialect.h"

namespace uprog::gold {

const dialect::Dialect& dialect();

}  // namespace uprog::gold
