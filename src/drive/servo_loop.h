// The cascaded controller: position P, velocity PI with velocity and acceleration feedforward,
// and a PI current loop that sets the winding voltage. Parallel form: u = KP * (e + KI * ∫e).
//
// Default gains (docs/drive.md) tune the default motor for a 1 kHz current loop, a 150 Hz
// velocity loop and a 200 1/s position loop.
#pragma once
#include <algorithm>
#include <cmath>

namespace uprog::drive {

struct Gains {
  // Index 0 is unused so that kp[n] matches the manual's KP[n]: 1 current, 2 velocity, 3 position.
  float kp[4] = {0.0f, 6.2832f, 9.0e-5f, 200.0f};  // V/A, A per count/s, 1/s
  float ki[4] = {0.0f, 1000.0f, 190.0f, 0.0f};     // 1/s
  float kv[3] = {0.0f, 1.0f, 1.0f};                // feedforward fractions: velocity, acceleration

  bool operator==(const Gains&) const = default;
};

struct LoopState {
  double velocity_integral = 0.0;  // ∫ velocity error dt, counts
  double position_integral = 0.0;  // ∫ position error dt, counts·s
  double current_integral = 0.0;   // ∫ current error dt, A·s
};

struct LoopInputs {
  double reference_position_counts;
  double reference_velocity_counts_per_s;
  double reference_accel_counts_per_s2;
  double feedback_position_counts;
  double feedback_velocity_counts_per_s;
  double accel_per_amp_counts_per_s2;
};

// The loops run once per servo cycle on the axis's critical path, so they are defined here,
// inline, where the axis's step can be compiled as one piece (no calls, state kept in registers).

// The velocity command of the position loop (UM=5).
inline double position_loop(const Gains& gains, LoopState& state, const LoopInputs& in, double dt_s) {
  const double error = in.reference_position_counts - in.feedback_position_counts;
  state.position_integral += error * dt_s;
  // With KI[3] = 0 (the default) the integral term is a signed zero, and error + ±0 is error
  // itself unless error is zero: said so, the integrator (three operations) leaves the servo
  // cycle's chain of dependent operations. Same result bit for bit.
  double with_integral = error;
  if (gains.ki[3] != 0.0f || error == 0.0 || !std::isfinite(state.position_integral)) [[unlikely]]
    with_integral = error + gains.ki[3] * state.position_integral;
  return gains.kv[1] * in.reference_velocity_counts_per_s + gains.kp[3] * with_integral;
}

// The current command of the velocity loop, clamped to ±current_limit_a; the integrator stops
// while the output is clamped.
inline double velocity_loop(const Gains& gains, LoopState& state, double velocity_command_counts_per_s,
                            const LoopInputs& in, double current_limit_a, double dt_s) {
  const double error = velocity_command_counts_per_s - in.feedback_velocity_counts_per_s;
  const double feedforward_a =
      gains.kv[2] * in.reference_accel_counts_per_s2 / in.accel_per_amp_counts_per_s2;
  const double candidate = state.velocity_integral + error * dt_s;
  const double unclamped = feedforward_a + gains.kp[2] * (error + gains.ki[2] * candidate);
  const double clamped = std::clamp(unclamped, -current_limit_a, current_limit_a);
  if (clamped == unclamped) state.velocity_integral = candidate;
  return clamped;
}

// The winding voltage of the current loop, clamped to ±bus_voltage_v.
inline double current_loop(const Gains& gains, LoopState& state, double current_command_a,
                           double current_a, double bus_voltage_v, double dt_s) {
  const double error = current_command_a - current_a;
  const double candidate = state.current_integral + error * dt_s;
  const double unclamped = gains.kp[1] * (error + gains.ki[1] * candidate);
  const double clamped = std::clamp(unclamped, -bus_voltage_v, bus_voltage_v);
  if (clamped == unclamped) state.current_integral = candidate;
  return clamped;
}

}  // namespace uprog::drive
