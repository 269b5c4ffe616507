// The motor-and-load model: a DC-equivalent servo motor (winding R, L, back-EMF) driving an
// inertia with viscous and Coulomb friction, integrated once per servo cycle.
//
// Defaults (documented in docs/drive.md): R = 1 ohm, L = 1 mH, Kt = Ke = 0.1 N·m/A,
// J = 1e-4 kg·m² (motor and load), viscous 1e-5 N·m·s/rad, Coulomb 5e-3 N·m,
// bus 48 V, encoder 65536 counts per revolution.
#pragma once
#include <cstdint>

namespace uprog::drive {

struct MotorModel {
  double resistance_ohm = 1.0;
  double inductance_h = 1e-3;
  double torque_constant_nm_per_a = 0.1;  // also the back-EMF constant in V·s/rad
  double inertia_kg_m2 = 1e-4;
  double viscous_friction_nm_s_per_rad = 1e-5;
  double coulomb_friction_nm = 5e-3;
  double bus_voltage_v = 48.0;
  double counts_per_rev = 65536.0;

  double counts_per_rad() const;
  // Acceleration per ampere of winding current, in counts/s² per A (used for feedforward).
  double accel_per_amp_counts_per_s2() const;
};

struct MotorState {
  double position_counts = 0.0;  // the encoder's exact (interpolated) position
  double velocity_counts_per_s = 0.0;
  double current_a = 0.0;
};

// What step_motor derives from the model and the cycle time alone: computed once per TS rather
// than once per cycle (an exp() and two divisions).
struct MotorStep {
  double dt_s = 0.0;
  double winding_decay = 1.0;  // exp(-dt R / L)
  double counts_per_rad = 1.0;
};
MotorStep motor_step_constants(const MotorModel& model, double dt_s);

// Advances the motor by dt_s with the winding voltage held at voltage_v (clamped to the bus).
// The electrical part is integrated exactly; the mechanics semi-implicitly.
void step_motor(const MotorModel& model, MotorState& state, double voltage_v, double dt_s);
// The same with the constants of motor_step_constants(model, dt_s).
void step_motor(const MotorModel& model, const MotorStep& step, MotorState& state, double voltage_v);

}  // namespace uprog::drive
