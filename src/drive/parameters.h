// The drive's configurable parameters: everything SV saves and LD loads (user variables, gains,
// limits, input logic, motion parameters, unit mode). Defaults are those of a fresh drive.
#pragma once
#include <array>
#include <cstdint>

#include "drive/servo_loop.h"

namespace uprog::drive {

constexpr int kUserVariableCount = 24;  // UI[1..24], UF[1..24]
constexpr int kInputCount = 6;
constexpr int kOutputCount = 4;

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

  // IL[n]: 7 = general purpose, active high: an unwired (low) input is inactive.
  std::array<int32_t, kInputCount> input_logic{7, 7, 7, 7, 7, 7};

  int32_t speed_counts_per_s = 10000;            // SP
  int32_t accel_counts_per_s2 = 100000;          // AC
  int32_t decel_counts_per_s2 = 100000;          // DC
  int32_t stop_decel_counts_per_s2 = 1000000;    // SD
  int32_t smoothing_ms = 0;                      // SF
  int32_t jog_velocity_counts_per_s = 0;         // JV
  int32_t unit_mode = 5;                         // UM
  int32_t servo_period_us = 50;                  // TS

  bool operator==(const Parameters&) const = default;
};

}  // namespace uprog::drive
