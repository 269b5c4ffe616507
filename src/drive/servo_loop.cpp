// The three nested loops, each a small pure step on explicit state.
#include "drive/servo_loop.h"

#include <algorithm>
#include <cmath>

namespace uprog::drive {

double position_loop(const Gains& gains, LoopState& state, const LoopInputs& in, double dt_s) {
  const double error = in.reference_position_counts - in.feedback_position_counts;
  state.position_integral += error * dt_s;
  return gains.kv[1] * in.reference_velocity_counts_per_s +
         gains.kp[3] * (error + gains.ki[3] * state.position_integral);
}

double velocity_loop(const Gains& gains, LoopState& state, double velocity_command_counts_per_s,
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

double current_loop(const Gains& gains, LoopState& state, double current_command_a,
                    double current_a, double bus_voltage_v, double dt_s) {
  const double error = current_command_a - current_a;
  const double candidate = state.current_integral + error * dt_s;
  const double unclamped = gains.kp[1] * (error + gains.ki[1] * candidate);
  const double clamped = std::clamp(unclamped, -bus_voltage_v, bus_voltage_v);
  if (clamped == unclamped) state.current_integral = candidate;
  return clamped;
}

}  // namespace uprog::drive
