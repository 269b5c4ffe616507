// The VM instructions of CUP's AMath[n] and ACompare[c] where the VM has the operation: what the
// loader emits for a line and the line runs' fused copies for the same line.
#pragma once
#include <cstdint>

#include "bytecode/code_builder.h"

namespace uprog::pup {

// Whether AMath[n] is VM instructions that cannot fail (a copy of lines may hold it); not the
// intrinsic functions (INTRIN), some of which fail on their domain.
bool math_in_vm(int32_t n);
// AMath[n] in VM instructions (an intrinsic function for sqrt, power and the reals); false
// (nothing emitted) where the firmware computes it.
bool emit_math(bytecode::CodeBuilder& b, int32_t n);
// Leaves 1/0 for condition c (2..10) on the stack.
void emit_condition(bytecode::CodeBuilder& b, int32_t c);

}  // namespace uprog::pup
