// The one display rule of docs/dialects/gold-command-line.md; the manual's examples that it
// does not reproduce are listed there.
#include "dialects/gold/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace uprog::gold {

std::string format_gold_int(int32_t value) { return std::to_string(value); }

std::string format_gold_float(float value) {
  const double v = value;
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const double magnitude = std::fabs(v);
  if (magnitude >= 1e7) {
    // Mantissa with six decimals, then "e" and the exponent in (at least) two digits.
    int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    double mantissa = v / std::pow(10.0, exponent);
    // Rounding to six decimals may carry into a new digit (9.9999996 -> 10.000000).
    if (std::fabs(std::round(mantissa * 1e6) / 1e6) >= 10.0) {
      mantissa /= 10.0;
      ++exponent;
    }
    std::snprintf(buffer, sizeof buffer, "%.6fe%s%02d", mantissa, exponent < 0 ? "-" : "",
                  exponent < 0 ? -exponent : exponent);
    return buffer;
  }
  if (v == std::floor(v)) {
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
  } else {
    // Six decimals, but no more than 7 significant digits (1.3.2: "123.45678 becomes 123.4568",
    // "2321.66458 becomes 2321.665"; 1.7: abs(-123.54) "is 123.5400").
    const int integer_digits = magnitude < 1.0 ? 0 : static_cast<int>(std::log10(magnitude)) + 1;
    const int decimals = std::clamp(7 - integer_digits, 1, 6);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  }
  return buffer;
}

}  // namespace uprog::gold
