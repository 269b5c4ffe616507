// The closed loop in motion: the acceptance move, smoothing, settling, modes and limits.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "axis_helpers.h"
#include "drive/axis.h"

namespace uprog::drive {
namespace {

using testing::enable;
using testing::run_us;
using testing::set_motion;

TEST(drive_axis_motion, AcceptanceMoveFollowsTrapezoidAndSettles) {
  Axis axis;
  ASSERT_EQ(axis.parameters().unit_mode, 5);
  enable(axis);
  ASSERT_TRUE(axis.servo_ready());
  ASSERT_EQ(axis.position(), 0);
  set_motion(axis, 50000, 1000000, 1000000);
  axis.set_absolute_target(100000);
  ASSERT_EQ(axis.begin(), Status::kOk);
  EXPECT_EQ(axis.motion_status(), 2);

  // Analytic trapezoid at 1.0 s: 1250 counts of ramp + 50000 * 0.95 s of cruise.
  run_us(axis, 1000000);
  const double expected_at_1s = 0.5 * 1e6 * 0.05 * 0.05 + 50000.0 * 0.95;
  EXPECT_NEAR(axis.position(), expected_at_1s, 0.01 * expected_at_1s);

  // The profile ends at 2.05 s; from 2.055 s on PX stays within 1 count of the target.
  run_us(axis, 1055000);
  for (int k = 0; k < 4000; ++k) {
    ASSERT_NEAR(axis.position(), 100000, 1) << "at cycle " << k << " after 2.055 s";
    axis.step();
  }
  EXPECT_EQ(axis.motion_status(), 0);
  EXPECT_EQ(axis.motor_fault(), 0u);
}

TEST(drive_axis_motion, EnableDelayThenServoReady) {
  Axis axis;
  EXPECT_EQ(axis.set_motor_on(true), Status::kOk);
  EXPECT_TRUE(axis.motor_on());
  run_us(axis, kEnableDelay_us - 50);
  EXPECT_FALSE(axis.servo_ready());
  EXPECT_EQ(axis.motion_status(), 3);  // the loop not yet closed: Gold's "motor off"
  axis.step();
  EXPECT_TRUE(axis.servo_ready());
  axis.set_motor_on(false);
  EXPECT_FALSE(axis.servo_ready());
}

// Reference jerk from third differences of the reference position.
double max_reference_jerk(Axis& axis, uint64_t us) {
  const double dt = axis.period_us() * 1e-6;
  double p[4] = {0, 0, 0, 0};
  double max_jerk = 0.0;
  for (uint64_t k = 0; k * axis.period_us() < us; ++k) {
    axis.step();
    p[0] = p[1];
    p[1] = p[2];
    p[2] = p[3];
    p[3] = axis.reference_position_exact();
    if (k >= 3)
      max_jerk = std::max(max_jerk, std::abs(p[3] - 3 * p[2] + 3 * p[1] - p[0]) / (dt * dt * dt));
  }
  return max_jerk;
}

TEST(drive_axis_motion, SmoothingBoundsJerkAndDelaysEndBySf) {
  const double accel = 1e6;
  const double sf_s = 0.010;
  Axis smooth;
  enable(smooth);
  set_motion(smooth, 50000, 1000000, 1000000);
  smooth.parameters().smoothing_ms = 10;
  smooth.set_absolute_target(20000);
  ASSERT_EQ(smooth.begin(), Status::kOk);
  // Trapezoid: 0.05 s ramps, 17500 counts of cruise (0.35 s): ends at 0.45 s, smoothed at 0.46 s.
  const double jerk = max_reference_jerk(smooth, 459000);
  EXPECT_LE(jerk, accel / sf_s * 1.001);
  EXPECT_GE(jerk, accel / sf_s * 0.9);
  EXPECT_TRUE(smooth.profiler_moving());
  run_us(smooth, 2000);
  EXPECT_FALSE(smooth.profiler_moving());
  EXPECT_EQ(smooth.reference_position_exact(), 20000.0);

  // The same move without smoothing has acceleration steps: the bound above would fail.
  Axis raw;
  enable(raw);
  set_motion(raw, 50000, 1000000, 1000000);
  raw.set_absolute_target(20000);
  raw.begin();
  EXPECT_GT(max_reference_jerk(raw, 459000), 100.0 * accel / sf_s);
}

TEST(drive_axis_motion, RelativeMovesAddToPreviousTarget) {
  Axis axis;
  enable(axis);
  set_motion(axis, 100000, 1000000, 1000000);
  axis.set_relative_move(3000);
  axis.begin();
  run_us(axis, 200000);
  axis.set_relative_move(-1000);
  axis.begin();
  run_us(axis, 200000);
  EXPECT_NEAR(axis.position(), 2000, 1);
  EXPECT_EQ(axis.relative_move(), -1000);
}

// ST brakes with SD, not DC (docs/dialects/gold.md, "ST").
TEST(drive_axis_motion, StopDeceleratesWithSd) {
  Axis axis;
  enable(axis);
  set_motion(axis, 20000, 1000000, 1000000);
  axis.parameters().stop_decel_counts_per_s2 = 200000;
  axis.set_jog_velocity(20000);
  axis.begin();
  run_us(axis, 100000);
  const double at_stop = axis.reference_position_exact();
  axis.stop();
  run_us(axis, 200000);  // 0.1 s of braking
  EXPECT_FALSE(axis.profiler_moving());
  EXPECT_NEAR(axis.reference_position_exact() - at_stop, 20000.0 * 20000.0 / (2 * 200000.0), 25.0);
}

TEST(drive_axis_motion, SoftwarePositionLimitsClampTargetsAndJogs) {
  Axis axis;
  enable(axis);
  set_motion(axis, 100000, 1000000, 1000000);
  axis.parameters().position_high_counts = 5000;
  axis.parameters().position_low_counts = -3000;
  axis.set_absolute_target(10000);
  axis.begin();
  run_us(axis, 300000);
  EXPECT_NEAR(axis.position(), 5000, 1);
  axis.set_jog_velocity(-50000);
  axis.begin();
  run_us(axis, 500000);
  EXPECT_NEAR(axis.position(), -3000, 1);
}

TEST(drive_axis_motion, VelocityLimitCapsSpeed) {
  Axis axis;
  enable(axis);
  set_motion(axis, 100000, 1000000, 1000000);
  axis.parameters().velocity_high_counts_per_s = 20000;
  axis.set_absolute_target(50000);
  axis.begin();
  int32_t peak = 0;
  for (int k = 0; k < 20000; ++k) {
    axis.step();
    peak = std::max(peak, axis.reference_velocity());
  }
  EXPECT_EQ(peak, 20000);
}

TEST(drive_axis_motion, ModuloWrapsPositionAndTakesShortestWay) {
  Axis axis;
  axis.parameters().modulo_low_counts = 0;
  axis.parameters().modulo_high_counts = 1000;
  enable(axis);
  set_motion(axis, 10000, 1000000, 1000000);
  axis.set_jog_velocity(10000);
  axis.begin();
  for (int k = 0; k < 4000; ++k) {
    axis.step();
    ASSERT_GE(axis.position(), 0);
    ASSERT_LT(axis.position(), 1000);
  }
  axis.stop();
  run_us(axis, 100000);
  const double before = axis.reference_position_exact();
  const int32_t here = axis.position();
  const int32_t target = (here + 900) % 1000;  // 100 counts backwards is shorter than 900 forward
  axis.set_absolute_target(target);
  axis.begin();
  run_us(axis, 100000);
  EXPECT_NEAR(axis.reference_position_exact() - before, -100.0, 1.0);
  EXPECT_NEAR(axis.position(), target, 1);
}

TEST(drive_axis_motion, VelocityModeTracksJog) {
  Axis axis;
  ASSERT_EQ(axis.set_unit_mode(2), Status::kOk);
  enable(axis);
  set_motion(axis, 1, 1000000, 1000000);
  axis.set_jog_velocity(30000);
  ASSERT_EQ(axis.begin(), Status::kOk);
  run_us(axis, 100000);
  EXPECT_NEAR(axis.velocity(), 30000, 300);
}

TEST(drive_axis_motion, CurrentModeAcceleratesAsKtOverJ) {
  Axis axis;
  ASSERT_EQ(axis.set_unit_mode(1), Status::kOk);
  enable(axis);
  EXPECT_EQ(axis.begin(), Status::kModeNotSupported);
  axis.set_torque_command(0.5f);
  run_us(axis, 5000);  // let the current loop settle
  const double v0 = axis.motor_state().velocity_counts_per_s;
  run_us(axis, 10000);
  const double measured = (axis.motor_state().velocity_counts_per_s - v0) / 0.010;
  const MotorModel& m = axis.motor_model();
  // Coulomb friction is at its full value once moving; viscous friction is negligible here.
  const double expected = (m.torque_constant_nm_per_a * 0.5 - m.coulomb_friction_nm) /
                          m.inertia_kg_m2 * m.counts_per_rad();
  EXPECT_NEAR(measured, expected, 0.03 * expected);
}

TEST(drive_axis_motion, PositionRedefinitionKeepsAxisStill) {
  Axis axis;
  enable(axis);
  axis.set_position(123456);
  EXPECT_EQ(axis.position(), 123456);
  run_us(axis, 50000);
  EXPECT_NEAR(axis.position(), 123456, 1);
  EXPECT_EQ(axis.position_error(), 0);
  set_motion(axis, 100000, 1000000, 1000000);
  axis.set_absolute_target(124456);
  axis.begin();
  run_us(axis, 200000);
  EXPECT_NEAR(axis.position(), 124456, 1);
}

TEST(drive_axis_motion, SeededRandomMovesAlwaysEndAtTarget) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int32_t> target(-200000, 200000), speed(1000, 200000),
      accel(100000, 5000000), smoothing(0, 20), interrupt_ms(0, 150);
  Axis axis;
  enable(axis);
  for (int move = 0; move < 30; ++move) {
    set_motion(axis, speed(rng), accel(rng), accel(rng));
    axis.parameters().smoothing_ms = smoothing(rng);
    axis.set_absolute_target(target(rng));
    ASSERT_EQ(axis.begin(), Status::kOk);
    run_us(axis, static_cast<uint64_t>(interrupt_ms(rng)) * 1000);
    const int32_t final_target = target(rng);
    axis.set_absolute_target(final_target);  // a new target while (maybe) still moving
    ASSERT_EQ(axis.begin(), Status::kOk);
    uint64_t waited_us = 0;
    while (axis.profiler_moving() && waited_us < 600000000) {
      axis.step();
      waited_us += axis.period_us();
    }
    run_us(axis, 50000);
    ASSERT_EQ(axis.motor_fault(), 0u) << "move " << move;
    ASSERT_NEAR(axis.position(), final_target, 1) << "move " << move;
  }
}

TEST(drive_axis_motion, SameInputsGiveBitIdenticalResults) {
  auto run = [] {
    Axis axis;
    enable(axis);
    set_motion(axis, 40000, 700000, 900000);
    axis.parameters().smoothing_ms = 7;
    axis.set_absolute_target(33333);
    axis.begin();
    run_us(axis, 300000);
    return axis.motor_state();
  };
  const MotorState a = run(), b = run();
  EXPECT_EQ(a.position_counts, b.position_counts);
  EXPECT_EQ(a.velocity_counts_per_s, b.velocity_counts_per_s);
  EXPECT_EQ(a.current_a, b.current_a);
}

}  // namespace
}  // namespace uprog::drive
