// Rounding the drive does in every servo cycle (PX, VX, PE, the recorder's samples) without a
// library call: the same results as std::lround (half away from zero) for every double.
#pragma once
#include <cmath>
#include <cstdint>

namespace uprog::drive {

// Below it an int64 holds the value with room, and the steps below are exact.
constexpr double kExactRoundingLimit = 4611686018427387904.0;  // 2^62

inline int64_t round_half_away(double x) {
  if (!(std::fabs(x) < kExactRoundingLimit))
    return std::lround(x);                             // NaN, huge: the library's answer
  const int64_t whole = static_cast<int64_t>(x);       // toward zero, exact
  const double rest = x - static_cast<double>(whole);  // exact: |rest| < 1
  // 2·rest is exact and truncates to 1 for rest >= 0.5, -1 for rest <= -0.5, else 0: no
  // branch, whose direction would be a coin toss for a moving axis (the recorder rounds five
  // signals a cycle).
  return whole + static_cast<int64_t>(2.0 * rest);
}

}  // namespace uprog::drive
