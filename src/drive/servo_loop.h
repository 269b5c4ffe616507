// The cascaded controller: position P, velocity PI with velocity and acceleration feedforward,
// and a PI current loop that sets the winding voltage. Parallel form: u = KP * (e + KI * ∫e).
//
// Default gains (docs/drive.md) tune the default motor for a 1 kHz current loop, a 150 Hz
// velocity loop and a 200 1/s position loop.
#pragma once
#include <algorithm>

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

// The loops run once per servo cycle and lie end to end on its chain of dependent operations
// (position feedback -> velocity command -> current command -> voltage -> motor -> position):
// they are inline so that the axis's step compiles as one piece, and each is written so that
// its error meets one multiplication and one addition. KP·(e + KI·(I + e·dt)) is computed as
// e·KP(1 + KI·dt) + KP·KI·I: the same value up to the last bits of the double, with the gain
// products and the integral term ready before the error is.

// The velocity command of the position loop (UM=5).
inline double position_loop(const Gains& gains, LoopState& state, const LoopInputs& in,
                            double dt_s) {
  const double kp = gains.kp[3], ki = gains.ki[3];
  const double ready =
      gains.kv[1] * in.reference_velocity_counts_per_s + kp * ki * state.position_integral;
  const double error = in.reference_position_counts - in.feedback_position_counts;
  state.position_integral += error * dt_s;
  return error * (kp * (1.0 + ki * dt_s)) + ready;
}

// The current command of the velocity loop, clamped to ±current_limit_a; the integrator stops
// while the output is clamped.
inline double velocity_loop(const Gains& gains, LoopState& state,
                            double velocity_command_counts_per_s, const LoopInputs& in,
                            double current_limit_a, double dt_s) {
  const double kp = gains.kp[2], ki = gains.ki[2];
  const double feedforward_a =
      gains.kv[2] * in.reference_accel_counts_per_s2 / in.accel_per_amp_counts_per_s2;
  const double ready = feedforward_a + kp * ki * state.velocity_integral;
  const double error = velocity_command_counts_per_s - in.feedback_velocity_counts_per_s;
  const double unclamped = error * (kp * (1.0 + ki * dt_s)) + ready;
  const double clamped = std::clamp(unclamped, -current_limit_a, current_limit_a);
  if (clamped == unclamped) state.velocity_integral += error * dt_s;
  return clamped;
}

// The winding voltage of the current loop, clamped to ±bus_voltage_v.
inline double current_loop(const Gains& gains, LoopState& state, double current_command_a,
                           double current_a, double bus_voltage_v, double dt_s) {
  const double kp = gains.kp[1], ki = gains.ki[1];
  const double ready = kp * ki * state.current_integral;
  const double error = current_command_a - current_a;
  const double unclamped = error * (kp * (1.0 + ki * dt_s)) + ready;
  const double clamped = std::clamp(unclamped, -bus_voltage_v, bus_voltage_v);
  if (clamped == unclamped) state.current_integral += error * dt_s;
  return clamped;
}

}  // namespace uprog::drive
