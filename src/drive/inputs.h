// Digital input functions as IL[n] encodes them: the value divided by two is the function, the
// lowest bit the polarity (odd = active high, even = active low).
#pragma once
#include <cstdint>

namespace uprog::drive {

enum class InputFunction : uint8_t {
  kInhibit = 0,        // IL 0/1
  kGeneralPurpose = 3, // IL 6/7
  kReverseLimit = 4,   // IL 8/9
  kForwardLimit = 5,   // IL 10/11
  kBegin = 6,          // IL 12/13
  kHome = 8,           // IL 16/17
  kHardStop = 10,      // IL 20/21
};

// True when `il` is one of the values the spec defines.
constexpr bool valid_input_logic(int32_t il) {
  switch (il / 2) {
    case 0: case 3: case 4: case 5: case 6: case 8: case 10: return il >= 0 && il <= 21;
    default: return false;
  }
}
constexpr InputFunction input_function(int32_t il) { return static_cast<InputFunction>(il / 2); }
constexpr bool input_active_high(int32_t il) { return (il & 1) != 0; }
// The logical (active) state of an input from its electrical level.
constexpr bool input_active(int32_t il, bool level_high) {
  return input_active_high(il) ? level_high : !level_high;
}

}  // namespace uprog::drive
