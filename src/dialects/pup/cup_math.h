// The numbered operations of AMath[n], ACompare[c] and AJump[c] (the spec's tables) as pure
// functions on int32: the one definition the compiler's folding, the host line's stack and the
// program's host calls share. Reals are fixed point: angles in mrad, other reals in thousandths.
#pragma once
#include <cstdint>
#include <optional>

#include "bytecode/intrinsics.h"

namespace uprog::pup {

// Values AMath[n] pops: 1 or 2; 0 for a number that is no operation.
int math_arity(int32_t n);
// The result of AMath[n] on `second` (2nd, below) and `first` (1st, the top); for a unary
// operation `second` is ignored. 0 with `*error` set to 30 (division by zero) or 31 (domain).
int32_t apply_math(int32_t n, int32_t second, int32_t first, int32_t* error);

// The VM's intrinsic function that computes AMath[n] (INTRIN), or nullopt where an opcode or
// the firmware does.
std::optional<bytecode::Intrinsic> intrinsic_of(int32_t n);

// Values the condition pops: 1 (POS, Z, NZ), 2 (EQ..LE), 0 for 1 (always) or no condition.
int condition_arity(int32_t c);
bool condition_holds(int32_t c, int32_t second, int32_t first);

}  // namespace uprog::pup
