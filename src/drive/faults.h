// Motor faults: the names a scenario or test injects and the MF bits each one latches.
// Bits follow the Elmo MF layout: single bits for feedback, current, tracking and limit faults;
// a power-stage fault sets bit 12 with a 3-bit code in bits 13..15 (docs/dialects/gold.md, "MF").
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

namespace uprog::drive {

enum FaultBits : uint32_t {
  kFaultFeedback = 0x00000004u,        // feedback loss
  kFaultOvercurrent = 0x00000008u,     // peak current exceeded
  kFaultVelocityError = 0x00000080u,   // |velocity error| > ER[2]
  kFaultFollowingError = 0x00000100u,  // |position error| > ER[3]
  kFaultPowerStage = 0x00001000u,      // bit 12: a power-stage fault; its code is bits 13..15
  kFaultUndervoltage = 0x00003000u,    // code 001
  kFaultOvervoltage = 0x00005000u,     // code 010
  kFaultShort = 0x0000B000u,           // code 101
  kFaultTemperature = 0x0000D000u,     // code 110
  kFaultSpeedLimit = 0x00020000u,      // VX < LL[2] or VX > HL[2]
  kFaultPositionLimit = 0x00400000u,   // PX < LL[3] or PX > HL[3] (UM=5)
};

constexpr uint32_t kPowerStageCodeShift = 13;  // MF bits 13..15, SR bits 1..3
// The 3-bit power-stage code of MF bits (0 when there is no power-stage fault).
constexpr uint32_t power_stage_code(uint32_t mf) {
  return (mf & kFaultPowerStage) != 0 ? (mf >> kPowerStageCodeShift) & 7u : 0u;
}

struct FaultName {
  std::string_view name;
  uint32_t bits;
};

// feedback, overcurrent, velocity_error, following_error, undervoltage, overvoltage, short,
// temperature, speed_limit, position_limit.
std::span<const FaultName> fault_names();
// 0 when no fault has that name.
uint32_t fault_bits(std::string_view name);

}  // namespace uprog::drive
