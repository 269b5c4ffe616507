// The arithmetic rules the manuals define, as pure functions: wrapping int add, saturating
// conversions and negation, promoting multiply. The VM, the preprocessor's constant evaluator
// and the tests' reference evaluator all use these, so there is one definition of each rule.
#pragma once
#include <cmath>
#include <cstdint>

namespace uprog::arith {

inline int32_t wrap_add(int32_t a, int32_t b) {
  return static_cast<int32_t>(static_cast<uint32_t>(a) + static_cast<uint32_t>(b));
}
inline int32_t wrap_sub(int32_t a, int32_t b) {
  return static_cast<int32_t>(static_cast<uint32_t>(a) - static_cast<uint32_t>(b));
}
inline int32_t wrap_mul(int32_t a, int32_t b) {
  return static_cast<int32_t>(static_cast<uint32_t>(a) * static_cast<uint32_t>(b));
}
// -INT32_MIN does not fit: it saturates to INT32_MAX (Gold manual 1.5).
inline int32_t saturating_neg(int32_t a) { return a == INT32_MIN ? INT32_MAX : -a; }
inline int32_t saturating_abs(int32_t a) { return a < 0 ? saturating_neg(a) : a; }

// Integer division truncates toward zero; INT32_MIN / -1 saturates. The caller checks b != 0.
inline int32_t int_div(int32_t a, int32_t b) {
  if (b == -1) return saturating_neg(a);
  return a / b;
}
inline int32_t int_rem(int32_t a, int32_t b) { return b == -1 ? 0 : a % b; }

// Shifts by a count outside 0..31 shift every bit out; >> is arithmetic.
inline int32_t shift_left(int32_t a, int32_t n) {
  if (n < 0 || n > 31) return 0;
  return static_cast<int32_t>(static_cast<uint32_t>(a) << n);
}
inline int32_t shift_right(int32_t a, int32_t n) {
  if (n < 0 || n > 31) return a < 0 ? -1 : 0;
  return a >> n;
}

// Float to int: NaN gives 0, out-of-range values saturate.
inline int32_t saturate_to_int(double v) {
  if (v != v) return 0;
  if (v >= 2147483647.0) return INT32_MAX;
  if (v <= -2147483648.0) return INT32_MIN;
  return static_cast<int32_t>(v);
}
// Rounds to nearest, halves away from zero (assignment of a float to an int, rnd()).
inline int32_t round_to_int(float v) { return saturate_to_int(std::round(static_cast<double>(v))); }
// Truncates toward zero (fix(), bitwise operands).
inline int32_t trunc_to_int(float v) { return saturate_to_int(static_cast<double>(v)); }

// Gold's int * int: the exact product if it fits, else the product as a float.
struct PromotedProduct {
  bool is_float;
  int32_t i;
  float f;
};
inline PromotedProduct promoting_mul(int32_t a, int32_t b) {
  const int64_t p = static_cast<int64_t>(a) * static_cast<int64_t>(b);
  if (p >= INT32_MIN && p <= INT32_MAX) return {false, static_cast<int32_t>(p), 0.0f};
  return {true, 0, static_cast<float>(p)};
}

// The low `bits` (1..31) of a, sign- or zero-extended: stores of 8- and 16-bit variables.
inline int32_t sign_extend(int32_t a, uint32_t bits) {
  const uint32_t shift = 32 - bits;
  return static_cast<int32_t>(static_cast<uint32_t>(a) << shift) >> shift;
}
inline int32_t zero_extend(int32_t a, uint32_t bits) {
  return static_cast<int32_t>(static_cast<uint32_t>(a) & ((1u << bits) - 1u));
}

// The word as an unsigned number.
inline int32_t shift_right_logical(int32_t a, int32_t n) {
  if (n < 0 || n > 31) return 0;
  return static_cast<int32_t>(static_cast<uint32_t>(a) >> n);
}

// a * b / c with the exact 64-bit product, truncating toward zero (ST's MULDIV). False when
// the quotient is no int32. The caller checks c != 0.
inline bool mul_div(int32_t a, int32_t b, int32_t c, int32_t& out) {
  const int64_t q = static_cast<int64_t>(a) * static_cast<int64_t>(b) / c;
  if (q < INT32_MIN || q > INT32_MAX) return false;
  out = static_cast<int32_t>(q);
  return true;
}

inline int32_t sign_of(float v) { return v > 0.0f ? 1 : (v < 0.0f ? -1 : 0); }
inline int32_t sign_of(int32_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

}  // namespace uprog::arith
