// The intrinsic functions (bytecode/intrinsics.def) as pure functions of their int arguments:
// INTRIN runs them, and a dialect that folds one at compile time or runs it on a host line calls
// the same, so that the three agree. Reals are computed in double, rounded and saturated.
#pragma once
#include <cmath>
#include <cstdint>

#include "bytecode/intrinsics.h"
#include "support/arith.h"
#include "vm/run_error.h"

namespace uprog::vm {

struct IntrinsicResult {
  int32_t value;
  RunError error;  // None, or DivisionByZero or Domain (then value is 0)
};

namespace intrinsic_detail {

// A real in thousandths, rounded to nearest and saturating; and back.
inline int32_t milli(double v) { return arith::saturate_to_int(std::round(v * 1000.0)); }
inline double real(int32_t thousandths) { return static_cast<double>(thousandths) / 1000.0; }

// The largest r with r * r <= v, for v >= 0.
inline int32_t int_sqrt(int32_t v) {
  auto r = static_cast<int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return static_cast<int32_t>(r);
}

// base to the power exponent (>= 0), saturating at the int range.
inline int32_t int_power(int32_t base, int32_t exponent) {
  int64_t result = 1;
  for (int32_t i = 0; i < exponent; ++i) {
    result *= base;
    if (result > INT32_MAX) return INT32_MAX;
    if (result < INT32_MIN) return INT32_MIN;
    if (result == 0 || result == 1) break;  // stays there
  }
  if (result == 1 && base == -1) return exponent % 2 == 0 ? 1 : -1;
  return static_cast<int32_t>(result);
}

inline uint32_t unsigned_of(int32_t v) { return static_cast<uint32_t>(v); }
inline int32_t int_of(uint32_t v) { return static_cast<int32_t>(v); }
constexpr IntrinsicResult ok(int32_t v) { return {v, RunError::None}; }
constexpr IntrinsicResult fail(RunError e) { return {0, e}; }

}  // namespace intrinsic_detail

// Function f on its arguments: a is the first pushed (the only one of a unary function), b the
// second (on top).
inline IntrinsicResult apply_intrinsic(bytecode::Intrinsic f, int32_t a, int32_t b = 0) {
  using namespace intrinsic_detail;
  using bytecode::Intrinsic;
  switch (f) {
    case Intrinsic::DIVU:
      return b == 0 ? fail(RunError::DivisionByZero) : ok(int_of(unsigned_of(a) / unsigned_of(b)));
    case Intrinsic::REMU:
      return b == 0 ? fail(RunError::DivisionByZero) : ok(int_of(unsigned_of(a) % unsigned_of(b)));
    case Intrinsic::ISQRT:
      return a < 0 ? fail(RunError::Domain) : ok(int_sqrt(a));
    case Intrinsic::IPOW:
      return b < 0 ? fail(RunError::Domain) : ok(int_power(a, b));
    case Intrinsic::SINM:
      return ok(milli(std::sin(real(a))));
    case Intrinsic::COSM:
      return ok(milli(std::cos(real(a))));
    case Intrinsic::TANM:
      return ok(milli(std::tan(real(a))));
    case Intrinsic::ASINM:
      return a < -1000 || a > 1000 ? fail(RunError::Domain) : ok(milli(std::asin(real(a))));
    case Intrinsic::ACOSM:
      return a < -1000 || a > 1000 ? fail(RunError::Domain) : ok(milli(std::acos(real(a))));
    case Intrinsic::ATANM:
      return ok(milli(std::atan(real(a))));
    case Intrinsic::ATAN2M:
      return ok(milli(std::atan2(static_cast<double>(a), static_cast<double>(b))));
    case Intrinsic::LNM:
      return a <= 0 ? fail(RunError::Domain) : ok(milli(std::log(real(a))));
    case Intrinsic::LOG10M:
      return a <= 0 ? fail(RunError::Domain) : ok(milli(std::log10(real(a))));
    case Intrinsic::EXPM:
      return ok(milli(std::exp(real(a))));
  }
  return fail(RunError::Domain);
}

}  // namespace uprog::vm
