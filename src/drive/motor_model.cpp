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

MotorStep motor_step_constants(const MotorModel& model, double dt_s) {
  MotorStep step;
  step.dt_s = dt_s;
  step.winding_decay = std::exp(-dt_s * model.resistance_ohm / model.inductance_h);
  step.counts_per_rad = model.counts_per_rad();
  step.rad_per_count = 1.0 / step.counts_per_rad;
  // 1 - decay without cancellation: -expm1(-dt R / L).
  const double rise = -std::expm1(-dt_s * model.resistance_ohm / model.inductance_h);
  step.amps_per_volt = rise / model.resistance_ohm;
  step.amps_per_counts_per_s =
      model.torque_constant_nm_per_a * rise / model.resistance_ohm / step.counts_per_rad;
  step.velocity_step_per_nm = step.counts_per_rad / model.inertia_kg_m2 * dt_s;
  step.velocity_step_per_a = model.torque_constant_nm_per_a * step.velocity_step_per_nm;
  step.velocity_step_per_v = step.amps_per_volt * step.velocity_step_per_a;
  step.position_step_per_v = step.velocity_step_per_v * dt_s;
  return step;
}

void step_motor(const MotorModel& model, MotorState& state, double voltage_v, double dt_s) {
  step_motor(model, motor_step_constants(model, dt_s), state, voltage_v);
}

}  // namespace uprog::drive
