// The reference semantics of Gold's numbers (manual 1.3-1.6, 1.10), written for the tests and
// independently of support/arith.h: int32 wrap-around, float32 rounding, promotions, conversions.
#pragma once
#include <cstdint>
#include <string>

namespace uprog::differential {

// A run-time typed number, as Gold sees it.
struct Num {
  bool is_float = false;
  int32_t i = 0;
  float f = 0.0f;
  static Num of_int(int32_t v) { return {false, v, 0.0f}; }
  static Num of_float(float v) { return {true, 0, v}; }
};

// The result of an evaluation: a number, or a run-time error (division by zero).
struct Outcome {
  bool division_by_zero = false;
  Num value;
};

bool same(const Num& a, const Num& b);  // same type and value; NaNs match, +0 matches -0
std::string describe(const Num& n);

namespace ref {
float to_float(const Num& n);      // int to float32, rounding to nearest even
float to_f32(double d);            // rounds a double to float32, overflowing to infinity
int32_t truncate_to_int(float x);  // toward zero, saturating, NaN 0 (bitwise operands, fix)
int32_t round_to_int(float x);     // nearest, halves away from zero, saturating (assignment, rnd)
bool truth(const Num& n);
}  // namespace ref

}  // namespace uprog::differential
