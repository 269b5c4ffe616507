// The reference number rules: each float operation is done exactly in double (which holds any
// float32 sum, difference, product or quotient closely enough) and rounded once to float32.
#include "reference.h"

#include <cfloat>
#include <cmath>
#include <cstring>
#include <sstream>

namespace uprog::differential {

bool same(const Num& a, const Num& b) {
  if (a.is_float != b.is_float) return false;
  if (!a.is_float) return a.i == b.i;
  if (std::isnan(a.f) && std::isnan(b.f)) return true;
  return a.f == b.f;  // +0 == -0: the manual does not tell them apart
}

std::string describe(const Num& n) {
  std::ostringstream s;
  if (n.is_float) {
    uint32_t bits;
    std::memcpy(&bits, &n.f, 4);
    s.precision(9);
    s << "float " << n.f << " (0x" << std::hex << bits << ")";
  } else {
    s << "int " << n.i;
  }
  return s.str();
}

namespace ref {

float to_float(const Num& n) { return n.is_float ? n.f : static_cast<float>(n.i); }

float to_f32(double d) {
  if (std::isfinite(d) && std::fabs(d) > FLT_MAX) {
    // Between FLT_MAX and FLT_MAX + half an ulp (2^103) rounds down; from there on, infinity.
    const double limit = static_cast<double>(FLT_MAX) + std::ldexp(1.0, 103);
    const float big = std::fabs(d) >= limit ? INFINITY : FLT_MAX;
    return d < 0 ? -big : big;
  }
  return static_cast<float>(d);
}

namespace {
int32_t saturate(double d) {
  if (d >= 2147483647.0) return INT32_MAX;
  if (d <= -2147483648.0) return INT32_MIN;
  return static_cast<int32_t>(d);
}
}  // namespace

int32_t truncate_to_int(float x) {
  if (std::isnan(x)) return 0;
  return saturate(std::trunc(static_cast<double>(x)));
}

int32_t round_to_int(float x) {
  if (std::isnan(x)) return 0;
  const double d = x;  // exact; d + 0.5 is exact too for every float
  return saturate(d < 0 ? -std::floor(-d + 0.5) : std::floor(d + 0.5));
}

bool truth(const Num& n) { return n.is_float ? n.f != 0.0f : n.i != 0; }

}  // namespace ref
}  // namespace uprog::differential
