// The motor-and-load model: a DC-equivalent servo motor (winding R, L, back-EMF) driving an
// inertia with viscous and Coulomb friction, integrated once per servo cycle.
//
// Defaults (documented in docs/drive.md): R = 1 ohm, L = 1 mH, Kt = Ke = 0.1 N·m/A,
// J = 1e-4 kg·m² (motor and load), viscous 1e-5 N·m·s/rad, Coulomb 5e-3 N·m,
// bus 48 V, encoder 65536 counts per revolution.
#pragma once
#include <algorithm>
#include <cmath>
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

// What step_motor derives from the model and the cycle time alone, computed once per TS: the
// exact solution of the winding over one cycle and the mechanics' step, as factors, so that
// the voltage meets two multiply-adds on its way to the velocity and no division.
struct MotorStep {
  double dt_s = 0.0;
  double winding_decay = 1.0;  // exp(-dt R / L)
  double counts_per_rad = 1.0;
  double rad_per_count = 1.0;  // 1 / counts_per_rad: the speed in rad/s is a multiplication away
  double amps_per_volt = 0.0;  // (1 - decay) / R: the current a held voltage adds
  double amps_per_counts_per_s = 0.0;  // Ke (1 - decay) / (R counts_per_rad): back-EMF's share
  double velocity_step_per_nm = 0.0;   // counts_per_rad / J * dt
  double velocity_step_per_a = 0.0;    // Kt velocity_step_per_nm: what a cycle's current adds
  double velocity_step_per_v = 0.0;    // amps_per_volt velocity_step_per_a
  double position_step_per_v = 0.0;    // velocity_step_per_v dt
};
MotorStep motor_step_constants(const MotorModel& model, double dt_s);

// Coulomb friction is smoothed over this speed, so that a stopped axis does not chatter between
// the two friction signs.
constexpr double kFrictionSmoothing_rad_per_s = 0.05;

// A smooth sign: tanh's [3/2] Padé approximant x(27 + x²)/(27 + 9x²), which reaches ±1 with a
// zero slope at x = ±3 and is held there. Within 2.4 % of tanh; a multiply-add chain and one
// division where a library tanh (an expm1 and a division) would lie on the servo cycle's chain of
// dependent operations whenever the axis is nearly stopped.
inline double smooth_sign(double x) {
  if (std::abs(x) >= 3.0) return std::copysign(1.0, x);
  const double x2 = x * x;
  return x * (27.0 + x2) / (27.0 + 9.0 * x2);
}

// Advances the motor by dt_s with the winding voltage held at voltage_v (clamped to the bus).
// The electrical part is integrated exactly; the mechanics semi-implicitly.
void step_motor(const MotorModel& model, MotorState& state, double voltage_v, double dt_s);

// The same with the constants of motor_step_constants(model, dt_s). Inline: it ends every servo
// cycle's chain of dependent operations (axis.cpp).
inline void step_motor(const MotorModel& model, const MotorStep& step, MotorState& state,
                       double voltage_v) {
  const double u = std::clamp(voltage_v, -model.bus_voltage_v, model.bus_voltage_v);
  const double omega_rad_per_s = state.velocity_counts_per_s * step.rad_per_count;
  // di/dt = (u - R i - Ke w) / L, solved exactly for a held voltage u and speed w:
  // i' = i decay + (u - Ke w)(1 - decay)/R.
  const double held_a = state.current_a * step.winding_decay -
                        state.velocity_counts_per_s * step.amps_per_counts_per_s;
  state.current_a = u * step.amps_per_volt + held_a;

  constexpr double kPerSmoothing = 1.0 / kFrictionSmoothing_rad_per_s;  // a multiply, not a divide
  const double friction_nm =
      model.viscous_friction_nm_s_per_rad * omega_rad_per_s +
      model.coulomb_friction_nm * smooth_sign(omega_rad_per_s * kPerSmoothing);
  // v' = v + (Kt i' - friction) counts_per_rad / J dt and x' = x + v' dt, written out in u: the
  // voltage meets one multiply-add on its way to each, the rest is ready before it is.
  const double coasting = state.velocity_counts_per_s - friction_nm * step.velocity_step_per_nm;
  const double velocity_without_voltage = held_a * step.velocity_step_per_a + coasting;
  state.velocity_counts_per_s = u * step.velocity_step_per_v + velocity_without_voltage;
  state.position_counts =
      u * step.position_step_per_v + (state.position_counts + velocity_without_voltage * step.dt_s);
}

}  // namespace uprog::drive
