// AMath, ACompare and AJump's numbered operations (cup_math.h).
#include "dialects/pup/cup_math.h"

#include "support/arith.h"
#include "vm/intrinsic.h"

namespace uprog::pup {
namespace {

using namespace arith;

int32_t fail(int32_t code, int32_t* error) {
  *error = code;
  return 0;
}

}  // namespace

// The AMath operations the VM computes as an intrinsic function (INTRIN), by the same code.
std::optional<bytecode::Intrinsic> intrinsic_of(int32_t n) {
  using bytecode::Intrinsic;
  switch (n) {
    case 8:
      return Intrinsic::ISQRT;
    case 9:
      return Intrinsic::IPOW;
    case 30:
      return Intrinsic::SINM;
    case 31:
      return Intrinsic::COSM;
    case 32:
      return Intrinsic::TANM;
    case 33:
      return Intrinsic::ASINM;
    case 34:
      return Intrinsic::ACOSM;
    case 35:
      return Intrinsic::ATANM;
    case 36:
      return Intrinsic::ATAN2M;
    case 40:
      return Intrinsic::LNM;
    case 41:
      return Intrinsic::LOG10M;
    case 42:
      return Intrinsic::EXPM;
    default:
      return std::nullopt;
  }
}

int math_arity(int32_t n) {
  switch (n) {
    case 1:
    case 2:
    case 3:
    case 4:
    case 5:
    case 9:
    case 10:
    case 11:
    case 12:
    case 14:
    case 15:
    case 20:
    case 21:
    case 36:
      return 2;
    case 6:
    case 7:
    case 8:
    case 13:
    case 22:
    case 30:
    case 31:
    case 32:
    case 33:
    case 34:
    case 35:
    case 40:
    case 41:
    case 42:
      return 1;
    default:
      return 0;
  }
}

int32_t apply_math(int32_t n, int32_t second, int32_t first, int32_t* error) {
  *error = 0;
  if (const auto f = intrinsic_of(n)) {
    // A binary function's first argument is the one below (`second`), a unary one's the top.
    const vm::IntrinsicResult r = math_arity(n) == 2 ? vm::apply_intrinsic(*f, second, first)
                                                     : vm::apply_intrinsic(*f, first);
    if (r.error == vm::RunError::DivisionByZero) return fail(30, error);
    if (r.error != vm::RunError::None) return fail(31, error);
    return r.value;
  }
  switch (n) {
    case 1:
      return wrap_add(second, first);
    case 2:
      return wrap_mul(second, first);
    case 3:
      return wrap_sub(second, first);
    case 4:
      return first == 0 ? fail(30, error) : int_div(second, first);
    case 5:
      return first == 0 ? fail(30, error) : int_rem(second, first);
    case 6:
      return saturating_neg(first);
    case 7:
      return saturating_abs(first);
    case 10:
      return second & first;
    case 11:
      return second | first;
    case 12:
      return second ^ first;
    case 13:
      return ~first;
    case 14:
      return shift_left(second, first);
    case 15:
      return shift_right(second, first);
    case 20:
      return (second != 0 && first != 0) ? 1 : 0;
    case 21:
      return (second != 0 || first != 0) ? 1 : 0;
    case 22:
      return first == 0 ? 1 : 0;
    default:
      return fail(31, error);
  }
}

int condition_arity(int32_t c) {
  if (c == 2 || c == 9 || c == 10) return 1;
  if (c >= 3 && c <= 8) return 2;
  return 0;
}

bool condition_holds(int32_t c, int32_t second, int32_t first) {
  switch (c) {
    case 1:
      return true;
    case 2:
      return first > 0;
    case 3:
      return second == first;
    case 4:
      return second != first;
    case 5:
      return second > first;
    case 6:
      return second >= first;
    case 7:
      return second < first;
    case 8:
      return second <= first;
    case 9:
      return first == 0;
    case 10:
      return first != 0;
    default:
      return false;
  }
}

}  // namespace uprog::pup
