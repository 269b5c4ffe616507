// Lowers an expression tree to uprog assembly that leaves its value in globals, in one of two
// styles: typed opcodes (ADDI, ADDF, I2F2, F2IT, ... with a wrapping MULI) or dynamic pairs
// (I2D, ADDD, MULD, CMPD, ... with Gold's promoting multiply).
#pragma once
#include <string>

#include "expr_tree.h"

namespace uprog::differential {

enum class AsmStyle { Typed, Pairs };

// A program whose routine "main" evaluates `e` and stores the result: Typed stores it in
// global "ri" (int) or "rf" (float) by its static type; Pairs stores value and tag in
// "rv" and "rt".
std::string asm_program(const Expr& e, const Vars& vars, AsmStyle style);

}  // namespace uprog::differential
