// Digital input functions as IL[n] encodes them: the value divided by two is the function, the
// lowest bit the polarity (odd = active high, even = active low); and the input port's bit layout.
#pragma once
#include <array>
#include <cstdint>

namespace uprog::drive {

// The functions IL 0..23 select (docs/dialects/gold.md, "Input functions").
enum class InputFunction : uint8_t {
  kInhibit,         // IL 0/1: the motor is held off while active
  kHardStop,        // IL 2/3 and 20/21: motion stops with SD and is held while active
  kIgnore,          // IL 4/5: no function; only the level is reported
  kGeneralPurpose,  // IL 6/7
  kReverseLimit,    // IL 8/9
  kForwardLimit,    // IL 10/11
  kBegin,           // IL 12/13: performs BG
  kSoftStop,        // IL 14/15: the motion in progress stops with SD
  kHome,            // IL 16/17: main home
  kAuxHome,         // IL 18/19: auxiliary home (reported; no auxiliary homing process)
  kAbort,           // IL 22/23: the motion in progress stops with SD
};

constexpr int32_t kInputLogicMax = 23;

constexpr bool valid_input_logic(int32_t il) { return il >= 0 && il <= kInputLogicMax; }

constexpr InputFunction input_function(int32_t il) {
  constexpr std::array<InputFunction, 12> kByPair{
      InputFunction::kInhibit,        InputFunction::kHardStop,     InputFunction::kIgnore,
      InputFunction::kGeneralPurpose, InputFunction::kReverseLimit, InputFunction::kForwardLimit,
      InputFunction::kBegin,          InputFunction::kSoftStop,     InputFunction::kHome,
      InputFunction::kAuxHome,        InputFunction::kHardStop,     InputFunction::kAbort};
  return valid_input_logic(il) ? kByPair[static_cast<size_t>(il / 2)] : InputFunction::kIgnore;
}
constexpr bool input_active_high(int32_t il) { return (il & 1) != 0; }
// The logical (active) state of an input from its electrical level.
constexpr bool input_active(int32_t il, bool level_high) {
  return input_active_high(il) ? level_high : !level_high;
}

// IP: bit n-1 is general-purpose input n active; bits 6..14 say which functions are active;
// bit 16 + n - 1 is the electrical level of input n. IB[n] is bit n.
enum InputPortBits : uint32_t {
  kIpGeneralPurpose1 = 1u << 0,  // input n: kIpGeneralPurpose1 << (n - 1)
  kIpMainHome = 1u << 6,
  kIpAuxHome = 1u << 7,
  kIpSoftStop = 1u << 8,
  kIpHardStop = 1u << 9,
  kIpForwardLimit = 1u << 10,
  kIpReverseLimit = 1u << 11,
  kIpInhibit = 1u << 12,
  kIpBegin = 1u << 13,
  kIpAbort = 1u << 14,
  kIpLevelShift = 16,  // input n's level: 1u << (kIpLevelShift + n - 1)
};

// The IP bit an active input of this function sets (0 for general purpose and ignore, which
// report through their own bits).
constexpr uint32_t input_function_bit(InputFunction f) {
  switch (f) {
    case InputFunction::kInhibit:
      return kIpInhibit;
    case InputFunction::kHardStop:
      return kIpHardStop;
    case InputFunction::kReverseLimit:
      return kIpReverseLimit;
    case InputFunction::kForwardLimit:
      return kIpForwardLimit;
    case InputFunction::kBegin:
      return kIpBegin;
    case InputFunction::kSoftStop:
      return kIpSoftStop;
    case InputFunction::kHome:
      return kIpMainHome;
    case InputFunction::kAuxHome:
      return kIpAuxHome;
    case InputFunction::kAbort:
      return kIpAbort;
    case InputFunction::kIgnore:
    case InputFunction::kGeneralPurpose:
      return 0;
  }
  return 0;
}

}  // namespace uprog::drive
