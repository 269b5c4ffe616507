// The ST dialect's entry for the registry (dialects/registry.cpp).
#pragma once
#include "dialect/dialect.h"

namespace uprog::st {

const dialect::Dialect& dialect();

}  // namespace uprog::st
