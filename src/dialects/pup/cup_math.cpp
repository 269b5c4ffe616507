// AMath, ACompare and AJump's numbered operations (cup_math.h).
#include "dialects/pup/cup_math.h"

#include <cmath>

#include "support/arith.h"

namespace uprog::pup {
namespace {

using namespace arith;

// A real result in thousandths (or mrad), rounded, saturating.
int32_t milli(double v) { return saturate_to_int(std::round(v * 1000.0)); }
double real(int32_t v) { return static_cast<double>(v) / 1000.0; }

int32_t int_sqrt(int32_t v) {
  auto r = static_cast<int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return static_cast<int32_t>(r);
}

int32_t int_power(int32_t base, int32_t exponent) {
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

int32_t fail(int32_t code, int32_t* error) {
  *error = code;
  return 0;
}

}  // namespace

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
    case 8:
      return first < 0 ? fail(31, error) : int_sqrt(first);
    case 9:
      return first < 0 ? fail(31, error) : int_power(second, first);
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
    case 30:
      return milli(std::sin(real(first)));
    case 31:
      return milli(std::cos(real(first)));
    case 32:
      return milli(std::tan(real(first)));
    case 33:
      return first < -1000 || first > 1000 ? fail(31, error) : milli(std::asin(real(first)));
    case 34:
      return first < -1000 || first > 1000 ? fail(31, error) : milli(std::acos(real(first)));
    case 35:
      return milli(std::atan(real(first)));
    case 36:
      return milli(std::atan2(static_cast<double>(second), static_cast<double>(first)));
    case 40:
      return first <= 0 ? fail(31, error) : milli(std::log(real(first)));
    case 41:
      return first <= 0 ? fail(31, error) : milli(std::log10(real(first)));
    case 42:
      return milli(std::exp(real(first)));
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
