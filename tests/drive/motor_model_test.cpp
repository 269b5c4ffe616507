// The motor model's smooth sign of Coulomb friction (drive/motor_model.h): tanh's [3/2] Padé
// approximant, odd, with tanh's slope at 0, within 2.4 % of tanh, rising to ±1 at ±3 with a zero
// slope and held there; and the friction a slowly turning motor feels.
#include "drive/motor_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uprog::drive {
namespace {

TEST(SmoothSign, IsOddWithTanhsSlopeAtZero) {
  EXPECT_EQ(smooth_sign(0.0), 0.0);
  for (const double x : {1e-9, 0.1, 0.7, 1.5, 2.9, 3.0, 10.0})
    EXPECT_EQ(smooth_sign(-x), -smooth_sign(x)) << x;
  // x(27 + x²)/(27 + 9x²) = x - 8x³/27 + ...: the slope at 0 is 1, as tanh's.
  const double h = 1e-6;
  EXPECT_NEAR(smooth_sign(h) / h, 1.0, 1e-9);
}

TEST(SmoothSign, StaysCloseToTanh) {
  for (int i = 0; i <= 4000; ++i) {
    const double x = i / 1000.0;
    EXPECT_NEAR(smooth_sign(x), std::tanh(x), 0.024) << x;
  }
  EXPECT_DOUBLE_EQ(smooth_sign(1.0), 28.0 / 36.0);  // the formula's own value
}

TEST(SmoothSign, RisesToOneAtThreeWithAZeroSlopeAndStaysThere) {
  double previous = 0.0;
  for (int i = 1; i <= 3000; ++i) {
    const double s = smooth_sign(i / 1000.0);
    EXPECT_GE(s, previous) << i;
    EXPECT_LE(s, 1.0) << i;
    previous = s;
  }
  EXPECT_EQ(smooth_sign(3.0), 1.0);
  EXPECT_EQ(smooth_sign(50.0), 1.0);
  EXPECT_EQ(smooth_sign(-1e300), -1.0);
  // Just below 3 the curve is flat: no kink where it is held at 1.
  EXPECT_NEAR((smooth_sign(3.0) - smooth_sign(3.0 - 1e-4)) / 1e-4, 0.0, 1e-4);
}

// At half the smoothing speed (0.025 rad/s) with no current the motor decelerates by the friction
// the approximant gives: viscous + Coulomb·s(0.5), s(0.5) = 0.5·27.25/29.25.
TEST(MotorModel, FrictionNearRestIsSmoothed) {
  const MotorModel m;
  const double dt = 50e-6;
  const MotorStep step = motor_step_constants(m, dt);
  MotorState state;
  const double omega = 0.5 * kFrictionSmoothing_rad_per_s;
  state.velocity_counts_per_s = omega * m.counts_per_rad();
  const double before = state.velocity_counts_per_s;
  // The voltage is the back-EMF's, so the winding's current stays (nearly) zero and the friction
  // decelerates the motor; the current's own small share is counted as it came out.
  step_motor(m, step, state, m.torque_constant_nm_per_a * omega);
  const double friction =
      m.viscous_friction_nm_s_per_rad * omega + m.coulomb_friction_nm * 0.5 * 27.25 / 29.25;
  const double expected_change = (m.torque_constant_nm_per_a * state.current_a - friction) /
                                 m.inertia_kg_m2 * dt * m.counts_per_rad();
  EXPECT_NEAR(state.velocity_counts_per_s - before, expected_change,
              1e-9 * std::abs(expected_change));
}

}  // namespace
}  // namespace uprog::drive
