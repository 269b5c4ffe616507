// Prints an expression tree as Gold text, with only the parentheses the manual's precedence
// table (1.4) needs, plus some the generator adds at random.
#pragma once
#include <string>

#include "expr_tree.h"

namespace uprog::differential {

// `noise_seed` picks which redundant parentheses are added.
std::string gold_text(const Expr& e, uint32_t noise_seed);
// "i0=...; i1=...; f0=...; ...; " assigning the variables.
std::string gold_assignments(const Vars& vars);

}  // namespace uprog::differential
