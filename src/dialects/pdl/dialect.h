// PDL's entry in the dialect registry.
#pragma once
#include "dialect/dialect.h"

namespace uprog::pdl {

const dialect::Dialect& dialect();

}  // namespace uprog::pdl
