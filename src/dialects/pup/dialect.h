// The Akribis AG300 dialect (PUP and CUP) for the registry.
#pragma once
#include "dialect/dialect.h"

namespace uprog::pup {

const dialect::Dialect& dialect();

}  // namespace uprog::pup
