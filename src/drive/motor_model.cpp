// Integration of the motor model for one servo cycle.
#include "drive/motor_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace uprog::drive {

double MotorModel::counts_per_rad() const { return counts_per_rev / (2.0 * std::numbers::pi); }

double MotorModel::accel_per_amp_counts_per_s2() const {
  return torque_constant_nm_per_a / inertia_kg_m2 * counts_per_rad();
}

namespace {

// tanh(x) rounds to exactly ±1 for |x| >= 22 (glibc returns 1 - tiny there): skip the call.
double saturating_tanh(double x) { return std::abs(x) >= 22.0 ? std::copysign(1.0, x) : std::tanh(x); }

}  // namespace

MotorStep motor_step_constants(const MotorModel& model, double dt_s) {
  return {dt_s, std::exp(-dt_s * model.resistance_ohm / model.inductance_h), model.counts_per_rad()};
}

void step_motor(const MotorModel& model, MotorState& state, double voltage_v, double dt_s) {
  step_motor(model, motor_step_constants(model, dt_s), state, voltage_v);
}

void step_motor(const MotorModel& model, const MotorStep& step, MotorState& state, double voltage_v) {
  const double dt_s = step.dt_s;
  const double v = std::clamp(voltage_v, -model.bus_voltage_v, model.bus_voltage_v);
  const double omega_rad_per_s = state.velocity_counts_per_s / step.counts_per_rad;
  // di/dt = (v - R i - Ke w) / L, solved exactly for a held voltage and speed.
  const double decay = step.winding_decay;
  const double steady_a = (v - model.torque_constant_nm_per_a * omega_rad_per_s) / model.resistance_ohm;
  state.current_a = steady_a + (state.current_a - steady_a) * decay;

  // Coulomb friction is smoothed near zero speed (tanh over 0.05 rad/s) so a stopped axis
  // does not chatter between the two friction signs.
  const double friction_nm = model.viscous_friction_nm_s_per_rad * omega_rad_per_s +
                             model.coulomb_friction_nm * saturating_tanh(omega_rad_per_s / 0.05);
  const double torque_nm = model.torque_constant_nm_per_a * state.current_a - friction_nm;
  const double accel_counts_per_s2 = torque_nm / model.inertia_kg_m2 * step.counts_per_rad;
  state.velocity_counts_per_s += accel_counts_per_s2 * dt_s;
  state.position_counts += state.velocity_counts_per_s * dt_s;
}

}  // namespace uprog::drive
