// Profiles checked against closed-form trapezoid results.
#include "drive/profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace uprog::drive {
namespace {

TEST(drive_profile, TrapezoidPositionsAndEndTime) {
  // 100000 counts at SP=50000, AC=DC=1e6: ramps of 0.05 s (1250 counts each), cruise 1.95 s.
  const Profile p = plan_move(0.0, 0.0, 100000.0, {50000.0, 1e6, 1e6});
  EXPECT_NEAR(p.duration_s(), 2.05, 1e-12);
  EXPECT_NEAR(sample(p, 0.025).position_counts, 0.5 * 1e6 * 0.025 * 0.025, 1e-9);
  EXPECT_NEAR(sample(p, 0.05).velocity_counts_per_s, 50000.0, 1e-9);
  EXPECT_NEAR(sample(p, 1.0).position_counts, 1250.0 + 50000.0 * 0.95, 1e-9);
  EXPECT_NEAR(sample(p, 2.025).position_counts, 100000.0 - 0.5 * 1e6 * 0.025 * 0.025, 1e-9);
  EXPECT_NEAR(sample(p, 2.05).position_counts, 100000.0, 1e-9);
  EXPECT_NEAR(sample(p, 5.0).position_counts, 100000.0, 1e-9);
  EXPECT_EQ(sample(p, 5.0).velocity_counts_per_s, 0.0);
}

TEST(drive_profile, TriangleWhenSpeedIsNotReached) {
  // d = v²/(2a) + v²/(2d) with a = 1e6, d = 4e6 over 1000 counts: v² = 1000 / (5/8e6) = 1.6e9.
  const Profile p = plan_move(0.0, 0.0, 1000.0, {1e9, 1e6, 4e6});
  const double peak = std::sqrt(1.6e9);
  EXPECT_NEAR(p.duration_s(), peak / 1e6 + peak / 4e6, 1e-12);
  EXPECT_NEAR(sample(p, peak / 1e6).velocity_counts_per_s, peak, 1e-6);
  EXPECT_NEAR(p.final_state().position_counts, 1000.0, 1e-9);
}

TEST(drive_profile, NegativeMoveMirrorsPositive) {
  const Profile p = plan_move(500.0, 0.0, -99500.0, {50000.0, 1e6, 1e6});
  EXPECT_NEAR(p.duration_s(), 2.05, 1e-12);
  EXPECT_NEAR(sample(p, 1.0).position_counts, 500.0 - 48750.0, 1e-9);
}

TEST(drive_profile, NewTargetBehindBrakesThenReturns) {
  // Moving at +50000 with DC=1e6: braking takes 0.05 s and 1250 counts, then 2250 back.
  const Profile p = plan_move(0.0, 50000.0, -1000.0, {50000.0, 1e6, 1e6});
  EXPECT_NEAR(sample(p, 0.0).velocity_counts_per_s, 50000.0, 1e-9);
  EXPECT_NEAR(sample(p, 0.05).position_counts, 1250.0, 1e-9);
  EXPECT_NEAR(sample(p, 0.05).velocity_counts_per_s, 0.0, 1e-9);
  const double back_peak = std::sqrt(2250.0 * 1e6);  // triangle of 2250 counts, a = d
  EXPECT_NEAR(p.duration_s(), 0.05 + 2.0 * back_peak / 1e6, 1e-12);
  EXPECT_NEAR(p.final_state().position_counts, -1000.0, 1e-9);
}

TEST(drive_profile, TargetTooCloseToStopOvershootsAndReturns) {
  const Profile p = plan_move(0.0, 50000.0, 100.0, {50000.0, 1e6, 1e6});
  EXPECT_GT(sample(p, 0.05).position_counts, 100.0);
  EXPECT_NEAR(p.final_state().position_counts, 100.0, 1e-9);
}

TEST(drive_profile, FasterThanSpeedSlowsDownFirst) {
  // From 80000 to SP=50000 at DC=1e6 takes 0.03 s.
  const Profile p = plan_move(0.0, 80000.0, 100000.0, {50000.0, 1e6, 1e6});
  EXPECT_NEAR(sample(p, 0.03).velocity_counts_per_s, 50000.0, 1e-9);
  EXPECT_NEAR(p.final_state().position_counts, 100000.0, 1e-9);
}

TEST(drive_profile, JogRampsToVelocityAndRunsOn) {
  const Profile p = plan_jog(0.0, 0.0, 20000.0, {1.0, 1e5, 1e6});
  EXPECT_NEAR(p.duration_s(), 0.2, 1e-12);
  EXPECT_NEAR(sample(p, 1.2).position_counts, 2000.0 + 20000.0, 1e-9);
  EXPECT_EQ(sample(p, 9.0).velocity_counts_per_s, 20000.0);
}

TEST(drive_profile, JogReversalBrakesWithDecelThenAccelerates) {
  const Profile p = plan_jog(0.0, 10000.0, -10000.0, {1.0, 1e5, 1e6});
  EXPECT_NEAR(p.duration_s(), 0.01 + 0.1, 1e-12);
  EXPECT_NEAR(sample(p, 0.01).velocity_counts_per_s, 0.0, 1e-9);
}

TEST(drive_profile, StopUsesGivenDeceleration) {
  const Profile p = plan_stop(100.0, -10000.0, 1e5);
  EXPECT_NEAR(p.duration_s(), 0.1, 1e-12);
  EXPECT_NEAR(p.final_state().position_counts, 100.0 - 500.0, 1e-9);
}

TEST(drive_profile, RandomMovesEndAtTargetWithinLimits) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> pos(-1e6, 1e6), vel(-2e5, 2e5), lim(1e3, 1e6);
  for (int i = 0; i < 2000; ++i) {
    const double start = pos(rng), v0 = vel(rng), target = pos(rng);
    const MotionLimits limits{lim(rng), lim(rng) * 10.0, lim(rng) * 10.0};
    const Profile p = plan_move(start, v0, target, limits);
    // Integrating the segments (not the stored target) must land on the target at rest.
    const ProfileSample end = sample(p, p.duration_s() * (1.0 - 1e-12));
    ASSERT_NEAR(end.position_counts, target, 1e-6 * (1.0 + std::abs(target)));
    const double a_max = std::max(limits.accel_counts_per_s2, limits.decel_counts_per_s2);
    ASSERT_NEAR(end.velocity_counts_per_s, 0.0, 2e-12 * p.duration_s() * a_max + 1e-6);
    ASSERT_EQ(p.final_state().velocity_counts_per_s, 0.0);
    const double vmax = std::max(limits.speed_counts_per_s, std::abs(v0)) * (1.0 + 1e-9);
    for (int k = 0; k <= 50; ++k) {
      const ProfileSample s = sample(p, p.duration_s() * k / 50.0);
      ASSERT_LE(std::abs(s.velocity_counts_per_s), vmax);
      ASSERT_LE(std::abs(s.accel_counts_per_s2),
                std::max(limits.accel_counts_per_s2, limits.decel_counts_per_s2));
    }
  }
}

}  // namespace
}  // namespace uprog::drive
