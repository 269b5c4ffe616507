// Motor faults: the names a scenario or test injects and the MF bits each one latches.
// Bits follow the Elmo convention: single bits for feedback, current and tracking faults, and a
// 4-bit code in bits 12..15 for the power stage (under/over-voltage, short, temperature).
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

namespace uprog::drive {

enum FaultBits : uint32_t {
  kFaultFeedback = 0x00000004u,         // feedback loss
  kFaultOvercurrent = 0x00000008u,      // peak current exceeded
  kFaultVelocityError = 0x00000080u,    // |velocity error| > ER[2]
  kFaultFollowingError = 0x00000100u,   // |position error| > ER[3]
  kFaultUndervoltage = 0x00001000u,
  kFaultOvervoltage = 0x00002000u,
  kFaultShort = 0x00003000u,
  kFaultTemperature = 0x00005000u,
  kFaultSpeedLimit = 0x00800000u,       // |VX| beyond the velocity limits
};

struct FaultName {
  std::string_view name;
  uint32_t bits;
};

// feedback, overcurrent, velocity_error, following_error, undervoltage, overvoltage, short,
// temperature, speed_limit.
std::span<const FaultName> fault_names();
// 0 when no fault has that name.
uint32_t fault_bits(std::string_view name);

}  // namespace uprog::drive
