// Digital inputs and their functions (IL), outputs, events, status words and time; the world's end
// stops.
#include <gtest/gtest.h>

#include "axis_helpers.h"
#include "drive/axis.h"
#include "drive/events.h"
#include "drive/inputs.h"

namespace uprog::drive {
namespace {

using testing::enable;
using testing::run_us;
using testing::set_motion;

TEST(drive_axis_io, PolarityEvenIsActiveLowOddIsActiveHigh) {
  Axis axis;
  ASSERT_EQ(axis.set_input_logic(1, 7), Status::kOk);
  ASSERT_EQ(axis.set_input_logic(2, 6), Status::kOk);
  EXPECT_FALSE(axis.input_active(1));
  EXPECT_TRUE(axis.input_active(2));    // unwired = low = active for an active-low input
  EXPECT_EQ(axis.input_port(), 0b10u);  // general-purpose input 2 is active; no level is high
  axis.set_input_level(1, true);
  axis.set_input_level(2, true);
  // Input 1 active; both levels high (bits 16 and 17).
  EXPECT_EQ(axis.input_port(), 0b01u | (0b11u << kIpLevelShift));
  EXPECT_EQ(axis.set_input_logic(1, 23), Status::kOk);  // abort, the last function
  EXPECT_EQ(axis.set_input_logic(1, 24), Status::kOutOfRange);
  EXPECT_EQ(axis.set_input_logic(1, -1), Status::kOutOfRange);
  EXPECT_EQ(axis.set_input_logic(7, 7), Status::kOutOfRange);
}

TEST(drive_axis_io, GeneralPurposeInputsReportActivationEdges) {
  Axis axis;
  axis.set_input_logic(4, 7);
  axis.set_input_logic(6, 6);
  axis.set_input_level(6, true);  // inactive (active low)
  axis.step();
  axis.set_input_level(4, true);
  EXPECT_EQ(axis.step(), general_input_event(4));
  EXPECT_EQ(axis.last_events(), general_input_event(4));
  EXPECT_EQ(axis.step(), 0u);  // held: no new edge
  axis.set_input_level(4, false);
  EXPECT_EQ(axis.step(), 0u);  // deactivation is not an event
  axis.set_input_level(6, false);
  EXPECT_EQ(axis.step(), general_input_event(6));
}

TEST(drive_axis_io, ForwardLimitStopsMotionWithSdAndBlocksThatDirection) {
  Axis axis;
  axis.set_input_logic(1, 11);
  enable(axis);
  set_motion(axis, 20000, 1000000, 1000000);
  axis.parameters().stop_decel_counts_per_s2 = 400000;
  axis.set_jog_velocity(20000);
  axis.begin();
  run_us(axis, 100000);
  const double at_switch = axis.reference_position_exact();
  axis.set_input_level(1, true);
  EXPECT_TRUE(axis.step() & kEventForwardLimit);
  run_us(axis, 100000);
  EXPECT_FALSE(axis.profiler_moving());
  // Stopping distance v²/(2 SD) = 500 counts.
  EXPECT_NEAR(axis.reference_position_exact() - at_switch, 500.0, 25.0);
  const double stopped = axis.reference_position_exact();
  axis.set_absolute_target(axis.position() + 5000);
  axis.begin();
  run_us(axis, 100000);
  EXPECT_NEAR(axis.reference_position_exact(), stopped, 1e-9);
  axis.set_absolute_target(axis.position() - 5000);  // away from the switch is allowed
  axis.begin();
  run_us(axis, 500000);
  EXPECT_NEAR(axis.reference_position_exact(), stopped - 5000.0, 1.0);
}

TEST(drive_axis_io, ReverseLimitStopsReverseMotion) {
  Axis axis;
  axis.set_input_logic(2, 8);  // active low
  axis.set_input_level(2, true);
  enable(axis);
  set_motion(axis, 20000, 1000000, 1000000);
  axis.set_jog_velocity(-20000);
  axis.begin();
  run_us(axis, 50000);
  axis.set_input_level(2, false);
  EXPECT_TRUE(axis.step() & kEventReverseLimit);
  run_us(axis, 100000);
  EXPECT_FALSE(axis.profiler_moving());
}

TEST(drive_axis_io, HardStopStopsAndHoldsWhileActive) {
  Axis axis;
  axis.set_input_logic(3, 21);
  enable(axis);
  set_motion(axis, 20000, 1000000, 1000000);
  axis.set_jog_velocity(20000);
  axis.begin();
  run_us(axis, 50000);
  axis.set_input_level(3, true);
  EXPECT_TRUE(axis.step() & kEventHardStop);
  run_us(axis, 100000);
  EXPECT_FALSE(axis.profiler_moving());
  const double held = axis.reference_position_exact();
  axis.begin();
  run_us(axis, 100000);
  EXPECT_EQ(axis.reference_position_exact(), held);
  axis.set_input_level(3, false);
  axis.begin();
  run_us(axis, 100000);
  EXPECT_GT(axis.reference_position_exact(), held + 100.0);
}

TEST(drive_axis_io, InhibitDisablesMotorAndReportsRelease) {
  Axis axis;
  axis.set_input_logic(2, 1);
  enable(axis);
  axis.set_input_level(2, true);
  axis.step();
  EXPECT_FALSE(axis.motor_on());
  EXPECT_EQ(axis.set_motor_on(true), Status::kInhibitActive);
  axis.set_input_level(2, false);
  EXPECT_EQ(axis.step(), static_cast<uint32_t>(kEventInhibitReleased));
  EXPECT_EQ(axis.set_motor_on(true), Status::kOk);
}

TEST(drive_axis_io, BeginInputPerformsBg) {
  Axis axis;
  axis.set_input_logic(2, 13);
  enable(axis);
  set_motion(axis, 100000, 1000000, 1000000);
  axis.set_absolute_target(9000);
  axis.set_input_level(2, true);
  EXPECT_EQ(axis.step(), static_cast<uint32_t>(kEventBegin));
  EXPECT_TRUE(axis.profiler_moving());
  run_us(axis, 300000);
  EXPECT_NEAR(axis.position(), 9000, 1);
}

TEST(drive_axis_io, HomeInputReportsEvent) {
  Axis axis;
  axis.set_input_logic(5, 17);
  axis.set_input_level(5, true);
  EXPECT_EQ(axis.step(), static_cast<uint32_t>(kEventHome));
}

TEST(drive_axis_io, ChangingInputLogicIsNotAnEdge) {
  Axis axis;
  axis.set_input_level(1, true);
  axis.step();  // GP input 1 became active: an event
  axis.set_input_logic(1, 11);
  EXPECT_EQ(axis.step(), 0u);
}

TEST(drive_axis_io, OutputsPortAndBits) {
  Axis axis;
  axis.set_output(3, true);
  EXPECT_EQ(axis.output_port(), 0b100u);
  axis.set_output_port(0xFF);
  EXPECT_EQ(axis.output_port(), 0xFu);
  axis.set_output(1, false);
  EXPECT_FALSE(axis.output(1));
  EXPECT_TRUE(axis.output(4));
}

TEST(drive_axis_io, StatusRegisterAndMotionStatus) {
  Axis axis;
  // UM=5 in bits 8..10, the two STO inputs (bits 14, 15) permit; MS=3: the motor is off.
  const uint32_t sto = kSrSafeTorqueOff1 | kSrSafeTorqueOff2;
  EXPECT_EQ(axis.status_register(), (5u << kSrUnitModeShift) | sto);
  EXPECT_EQ(axis.motion_status(), 3);
  enable(axis);
  EXPECT_EQ(axis.status_register(), kSrMotorOn | (5u << kSrUnitModeShift) | sto);
  EXPECT_EQ(axis.motion_status(), 1);  // no point-to-point target yet: MS=0 does not apply
  axis.set_absolute_target(1000);
  axis.begin();
  EXPECT_EQ(axis.status_register() & sto, sto);
  EXPECT_EQ(axis.motion_status(), 2);
}

TEST(drive_axis_io, TimeAdvancesByTsAndWraps) {
  Axis axis;
  axis.set_time_us(0xFFFFFF00u);
  run_us(axis, 500);
  EXPECT_EQ(axis.time_us(), static_cast<uint32_t>(0xFFFFFF00u + 500u));
  ASSERT_EQ(axis.set_period_us(100), Status::kOk);
  axis.step();
  EXPECT_EQ(axis.time_us(), static_cast<uint32_t>(0xFFFFFF00u + 600u));
  EXPECT_EQ(axis.set_period_us(10), Status::kOutOfRange);
}

}  // namespace
}  // namespace uprog::drive

namespace uprog::drive {
namespace {

// The world's end stops (docs/drive.md): a move beyond one ends at the stop itself, and the
// reference running on builds the following error against it.
TEST(drive_axis_world, EndStopHoldsTheLoadAndTheFollowingErrorGrows) {
  Axis axis;
  axis.parameters().max_position_error_counts = 2000000000;  // watch PE grow, no fault
  axis.parameters().max_velocity_error_counts_per_s = 2000000000;
  axis.place_end_stops(-1000.0, 5000.0);
  testing::enable(axis);
  testing::set_motion(axis, 50000, 1000000, 1000000);
  axis.set_absolute_target(20000);
  axis.begin();
  testing::run_us(axis, 1000000);  // the profile reaches 20000 within 0.45 s
  EXPECT_EQ(axis.position(), 5000);
  EXPECT_EQ(axis.position_error(), 15000);  // the reference at 20000, the load at the stop
  // The world outlives a fresh axis (the controller's reboot carries it).
  Axis fresh;
  fresh.place_world(axis.world());
  testing::enable(fresh);
  testing::set_motion(fresh, 50000, 1000000, 1000000);
  fresh.set_absolute_target(-8000);
  fresh.begin();
  testing::run_us(fresh, 1000000);
  EXPECT_EQ(fresh.position(), -1000);
}

}  // namespace
}  // namespace uprog::drive
