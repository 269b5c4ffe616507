// The drive's configurable parameters: everything SV saves and LD loads (user variables, gains,
// limits, input logic, motion parameters, unit mode, target window, feedback setup). Defaults
// are those of a fresh drive.
#pragma once
#include <array>
#include <cstdint>

#include "drive/servo_loop.h"

namespace uprog::drive {

constexpr int kUserVariableCount = 24;  // UI[1..24], UF[1..24]
constexpr int kInputCount = 6;
constexpr int kOutputCount = 4;
constexpr int kCommutationCount = 57;  // CA[1..57]

constexpr int kCountsPerRevolutionIndex = 18;  // CA[18]

constexpr std::array<int32_t, kCommutationCount> default_commutation() {
  std::array<int32_t, kCommutationCount> ca{};
  ca[kCountsPerRevolutionIndex - 1] = 65536;  // the default motor's encoder (motor_model.h)
  ca[19 - 1] = 1;                             // CA[19]: pole pairs
  return ca;
}

struct Parameters {
  // User variables; index 0 is UI[1].
  std::array<int32_t, kUserVariableCount> user_ints{};
  std::array<float, kUserVariableCount> user_floats{};

  Gains gains;
  float continuous_current_a = 3.0f;  // CL[1]
  float peak_current_a = 6.0f;        // PL[1]

  int32_t max_velocity_error_counts_per_s = 100000;  // ER[2]
  int32_t max_position_error_counts = 5000;          // ER[3]
  int32_t velocity_high_counts_per_s = 2000000;      // VH[2]
  int32_t velocity_low_counts_per_s = -2000000;      // VL[2]
  int32_t position_high_counts = 1000000000;         // VH[3]
  int32_t position_low_counts = -1000000000;         // VL[3]
  int32_t modulo_low_counts = 0;                     // XM[1]
  int32_t modulo_high_counts = 0;                    // XM[2]; XM[1] == XM[2] means no modulo
  // Feedback limits: beyond them a fault latches (MF 0x20000 speed, 0x400000 position).
  int32_t speed_fault_high_counts_per_s = 2400000;      // HL[2]
  int32_t speed_fault_low_counts_per_s = -2400000;      // LL[2]
  int32_t position_fault_high_counts = 2147483647;      // HL[3]: by default never reached
  int32_t position_fault_low_counts = -2147483647 - 1;  // LL[3]

  // MS=0 once |target - position| <= TR[1] for TR[2] ms after a point-to-point move.
  int32_t target_radius_counts = 100;  // TR[1]
  int32_t target_time_ms = 20;         // TR[2]

  // IL[n]: 7 = general purpose, active high: an unwired (low) input is inactive. Changed only
  // through Axis::set_input_logic() or load_parameters(), which rescan the inputs.
  std::array<int32_t, kInputCount> input_logic{7, 7, 7, 7, 7, 7};

  int32_t speed_counts_per_s = 10000;          // SP
  int32_t accel_counts_per_s2 = 100000;        // AC
  int32_t decel_counts_per_s2 = 100000;        // DC
  int32_t stop_decel_counts_per_s2 = 1000000;  // SD
  int32_t smoothing_ms = 0;                    // SF[1] (SF)
  int32_t smoothing2_ms = 0;                   // SF[2]: stored, no effect (gold.md)
  int32_t final_speed_counts_per_s = 0;        // FS: stored, no effect (gold.md)
  int32_t reference_mode = 0;                  // RM: 0 none, 1 external (SR bit 5)
  std::array<int32_t, 2> brake_delay_ms{};     // BP[1], BP[2]: stored, no brake simulated
  std::array<int32_t, 12> feedback_config{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};  // FC[1..12]
  std::array<int32_t, 16> stop_config{};                                        // SC[1..16]: stored
  int32_t jog_velocity_counts_per_s = 0;                                        // JV
  int32_t unit_mode = 5;                                                        // UM
  int32_t servo_period_us = 50;                                                 // TS
  int32_t profiler_mode = 1;  // PM: 1 UM=2 ramps to JV with AC/DC, 0 jumps

  // Feedback and commutation set-up, index 0 is CA[1]. The encoder's counts per revolution
  // (CA[18]) space the index pulses; the others are stored for programs that read them.
  std::array<int32_t, kCommutationCount> commutation = default_commutation();

  int32_t counts_per_revolution() const { return commutation[kCountsPerRevolutionIndex - 1]; }

  bool operator==(const Parameters&) const = default;
};

}  // namespace uprog::drive
