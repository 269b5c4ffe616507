// The cascaded controller: position P, velocity PI with velocity and acceleration feedforward,
// and a PI current loop that sets the winding voltage. Parallel form: u = KP * (e + KI * ∫e).
//
// Default gains (docs/drive.md) tune the default motor for a 1 kHz current loop, a 150 Hz
// velocity loop and a 200 1/s position loop.
#pragma once

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

// The velocity command of the position loop (UM=5).
double position_loop(const Gains& gains, LoopState& state, const LoopInputs& in, double dt_s);

// The current command of the velocity loop, clamped to ±current_limit_a; the integrator stops
// while the output is clamped.
double velocity_loop(const Gains& gains, LoopState& state, double velocity_command_counts_per_s,
                     const LoopInputs& in, double current_limit_a, double dt_s);

// The winding voltage of the current loop, clamped to ±bus_voltage_v.
double current_loop(const Gains& gains, LoopState& state, double current_command_a,
                    double current_a, double bus_voltage_v, double dt_s);

}  // namespace uprog::drive
