// Faults: tracking errors latch, injected faults by name, and what MO=1 does afterwards.
#include <gtest/gtest.h>

#include "axis_helpers.h"
#include "drive/axis.h"
#include "drive/events.h"
#include "drive/faults.h"

namespace uprog::drive {
namespace {

using testing::enable;
using testing::run_us;
using testing::set_motion;

TEST(drive_axis_fault, FollowingErrorLatchesAndOpensLoop) {
  Axis axis;
  axis.parameters().peak_current_a = 0.02f;  // too weak to follow
  axis.parameters().max_position_error_counts = 200;
  axis.parameters().max_velocity_error_counts_per_s = 2000000000;  // isolate the position check
  enable(axis);
  set_motion(axis, 100000, 10000000, 10000000);
  axis.set_absolute_target(100000);
  axis.begin();
  const uint32_t events = run_us(axis, 100000);
  EXPECT_TRUE(events & kEventFault);
  EXPECT_EQ(axis.motor_fault(), static_cast<uint32_t>(kFaultFollowingError));
  EXPECT_FALSE(axis.motor_on());
  EXPECT_EQ(axis.status_register() & kSrMotorFailure, kSrMotorFailure);
  EXPECT_EQ(axis.status_register() & kSrDriveProblem, 0u);  // not a power-stage problem
  EXPECT_EQ(axis.motion_status(), 3);                       // the motor is off
  // The cause is gone once the motor is off: MO=1 succeeds and clears MF.
  EXPECT_EQ(axis.set_motor_on(true), Status::kOk);
  EXPECT_EQ(axis.motor_fault(), 0u);
}

TEST(drive_axis_fault, NoFollowingErrorWithDefaultGains) {
  Axis axis;
  enable(axis);
  set_motion(axis, 50000, 1000000, 1000000);
  axis.set_absolute_target(100000);
  axis.begin();
  EXPECT_FALSE(run_us(axis, 2500000) & kEventFault);
}

TEST(drive_axis_fault, VelocityErrorLatches) {
  Axis axis;
  axis.set_unit_mode(2);
  axis.parameters().peak_current_a = 0.02f;
  axis.parameters().max_velocity_error_counts_per_s = 5000;
  enable(axis);
  set_motion(axis, 1, 10000000, 10000000);
  axis.set_jog_velocity(100000);
  axis.begin();
  EXPECT_TRUE(run_us(axis, 50000) & kEventFault);
  EXPECT_EQ(axis.motor_fault(), static_cast<uint32_t>(kFaultVelocityError));
}

TEST(drive_axis_fault, EveryNamedFaultCanBeInjected) {
  for (const FaultName& f : fault_names()) {
    Axis axis;
    enable(axis);
    ASSERT_TRUE(axis.inject_fault(f.name)) << f.name;
    EXPECT_EQ(axis.motor_fault(), f.bits) << f.name;
    EXPECT_FALSE(axis.motor_on());
    EXPECT_EQ(axis.step(), static_cast<uint32_t>(kEventFault)) << f.name;
  }
  Axis axis;
  EXPECT_FALSE(axis.inject_fault("no_such_fault"));
  EXPECT_EQ(axis.motor_fault(), 0u);
}

TEST(drive_axis_fault, PersistentCauseRefusesEnableUntilCleared) {
  Axis axis;
  enable(axis);
  ASSERT_TRUE(axis.inject_fault("undervoltage", true));
  EXPECT_EQ(axis.set_motor_on(true), Status::kFaultLatched);
  EXPECT_EQ(axis.motor_fault(), static_cast<uint32_t>(kFaultUndervoltage));
  axis.clear_fault_cause("undervoltage");
  EXPECT_EQ(axis.set_motor_on(true), Status::kOk);
  EXPECT_EQ(axis.motor_fault(), 0u);
}

TEST(drive_axis_fault, MotorOffRulesForModeAndBegin) {
  Axis axis;
  EXPECT_EQ(axis.begin(), Status::kMotorOff);
  enable(axis);
  EXPECT_EQ(axis.set_unit_mode(2), Status::kMotorOn);
  axis.set_motor_on(false);
  EXPECT_EQ(axis.set_unit_mode(3), Status::kOutOfRange);
  EXPECT_EQ(axis.set_unit_mode(2), Status::kOk);
}

}  // namespace
}  // namespace uprog::drive
