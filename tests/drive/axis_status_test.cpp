// The status words as the Elmo reference lays them out: MS through TR[1]/TR[2], SR's bits, IP's
// bits for every input function, the LL/HL fault limits, soft stop, abort and ignore, PM and PT.
#include <gtest/gtest.h>

#include "axis_helpers.h"
#include "drive/axis.h"
#include "drive/events.h"
#include "drive/faults.h"
#include "drive/inputs.h"

namespace uprog::drive {
namespace {

using testing::enable;
using testing::run_us;
using testing::set_motion;

// Gold's SR bits 14 and 15 are the STO inputs, both set (docs/dialects/gold.md, "SR").
uint32_t sr_sto_bits(const Axis& axis) { return (axis.status_register() >> 14) & 3u; }

// A 10000-count move at SP=50000, AC=DC=1e6: 0.05 s ramps and 0.15 s of cruise, 0.25 s in all.
void start_move(Axis& axis) {
  set_motion(axis, 50000, 1000000, 1000000);
  axis.set_absolute_target(axis.position() + 10000);
  ASSERT_EQ(axis.begin(), Status::kOk);
}

TEST(drive_status, MsSettlesThroughTargetRadiusAndTime) {
  Axis axis;
  enable(axis);
  axis.parameters().target_radius_counts = 100;  // TR[1]
  axis.parameters().target_time_ms = 20;         // TR[2]
  start_move(axis);
  EXPECT_EQ(axis.motion_status(), 2);
  run_us(axis, 240000);
  EXPECT_EQ(axis.motion_status(), 2);
  run_us(axis, 20000);  // 10 ms after the profile's end: the reference stands, not yet settled
  EXPECT_EQ(axis.motion_status(), 1);
  EXPECT_EQ(sr_sto_bits(axis), 3u);
  run_us(axis, 20000);  // 30 ms after: within TR[1] for more than TR[2]
  EXPECT_EQ(axis.motion_status(), 0);
  EXPECT_EQ(sr_sto_bits(axis), 3u);
}

TEST(drive_status, AtRestWhenOffStoppedOrSettled) {
  Axis axis;
  EXPECT_TRUE(axis.at_rest());  // the motor is off
  enable(axis);
  EXPECT_TRUE(axis.at_rest());  // on, nothing commanded
  start_move(axis);
  EXPECT_FALSE(axis.at_rest());
  run_us(axis, 260000);  // the profile ended, TR[2] not yet over: still settling
  EXPECT_FALSE(axis.at_rest());
  run_us(axis, 20000);
  EXPECT_TRUE(axis.at_rest());
}

TEST(drive_status, MsZeroTargetTimeSettlesWithTheProfile) {
  Axis axis;
  enable(axis);
  axis.parameters().target_time_ms = 0;
  start_move(axis);
  run_us(axis, 250100);  // the profile ended 0.1 ms ago
  EXPECT_EQ(axis.motion_status(), 0);
}

TEST(drive_status, MsAfterAStoppedJogStaysOne) {
  // "Value 0 is applicable only when there is a defined position target, as in PTP."
  Axis axis;
  enable(axis);
  set_motion(axis, 20000, 1000000, 1000000);
  axis.set_jog_velocity(20000);
  axis.begin();
  run_us(axis, 100000);
  EXPECT_EQ(axis.motion_status(), 2);  // a position-mode jog is a profiler motion
  axis.stop();
  run_us(axis, 500000);
  EXPECT_EQ(axis.motion_status(), 1);
}

TEST(drive_status, MsInVelocityModeFollowsTheRamp) {
  Axis axis;
  ASSERT_EQ(axis.set_unit_mode(2), Status::kOk);
  enable(axis);
  set_motion(axis, 1, 1000000, 1000000);
  axis.set_jog_velocity(50000);
  axis.begin();
  EXPECT_EQ(axis.motion_status(), 2);  // accelerating to JV: 0.05 s
  run_us(axis, 40000);
  EXPECT_EQ(axis.motion_status(), 2);
  run_us(axis, 20000);
  EXPECT_EQ(axis.motion_status(), 1);  // the reference equals the JV target
  EXPECT_TRUE(axis.profiler_moving());
}

TEST(drive_status, NoProfilerInVelocityModeStepsToJv) {
  Axis axis;
  ASSERT_EQ(axis.set_unit_mode(2), Status::kOk);
  axis.parameters().profiler_mode = 0;  // PM=0
  enable(axis);
  axis.set_jog_velocity(30000);
  axis.begin();
  axis.step();
  EXPECT_EQ(axis.reference_velocity(), 30000);
  EXPECT_EQ(axis.motion_status(), 1);  // "always the case if no profiler mode is used: PM=0"
}

TEST(drive_status, SrPowerStageCodeAndMotorFailure) {
  struct Case {
    const char* fault;
    uint32_t low_bits;
  };
  // SR bit 0 "problem", bits 1..3 the MF power-stage code (reference SR table, bits 1-3).
  for (const Case& c : {Case{"undervoltage", 0x3u}, Case{"overvoltage", 0x5u}, Case{"short", 0xBu},
                        Case{"temperature", 0xDu}, Case{"feedback", 0x0u}}) {
    Axis axis;
    enable(axis);
    ASSERT_TRUE(axis.inject_fault(c.fault));
    EXPECT_EQ(axis.status_register() & 0xFu, c.low_bits) << c.fault;
    EXPECT_EQ(axis.status_register() & kSrMotorFailure, kSrMotorFailure) << c.fault;
    EXPECT_EQ(axis.status_register() & kSrMotorOn, 0u) << c.fault;
  }
}

TEST(drive_status, SrUnitModeAndStoppedByLimit) {
  Axis axis;
  ASSERT_EQ(axis.set_unit_mode(2), Status::kOk);
  EXPECT_EQ((axis.status_register() >> kSrUnitModeShift) & 7u, 2u);
  ASSERT_EQ(axis.set_unit_mode(5), Status::kOk);
  axis.set_input_logic(1, 11);  // forward limit
  enable(axis);
  set_motion(axis, 20000, 1000000, 1000000);
  axis.set_jog_velocity(20000);
  axis.begin();
  run_us(axis, 50000);
  EXPECT_EQ(axis.status_register() & kSrStoppedByLimit, 0u);
  axis.set_input_level(1, true);
  run_us(axis, 100000);
  EXPECT_EQ(axis.status_register() & kSrStoppedByLimit, kSrStoppedByLimit);
  EXPECT_EQ(axis.input_port() & kIpForwardLimit, kIpForwardLimit);
  axis.set_absolute_target(axis.position() - 1000);  // away from the switch
  axis.begin();
  EXPECT_EQ(axis.status_register() & kSrStoppedByLimit, 0u);  // until the next BG
}

TEST(drive_status, SrStoppedBySoftwarePositionLimit) {
  Axis axis;
  enable(axis);
  axis.parameters().position_high_counts = 3000;  // VH[3]
  start_move(axis);                               // to 10000: clamped to 3000
  run_us(axis, 50000);
  EXPECT_EQ(axis.status_register() & kSrStoppedByLimit, 0u);  // still on its way
  run_us(axis, 300000);
  EXPECT_EQ(axis.status_register() & kSrStoppedByLimit, kSrStoppedByLimit);
  EXPECT_NEAR(axis.position(), 3000, 1);
}

TEST(drive_status, InputPortBitForEveryFunction) {
  struct Case {
    int32_t il;
    uint32_t bit;
  };
  const uint32_t level1 = 1u << kIpLevelShift;
  for (const Case& c :
       {Case{1, kIpInhibit}, Case{3, kIpHardStop}, Case{5, 0}, Case{7, kIpGeneralPurpose1},
        Case{9, kIpReverseLimit}, Case{11, kIpForwardLimit}, Case{13, kIpBegin},
        Case{15, kIpSoftStop}, Case{17, kIpMainHome}, Case{19, kIpAuxHome}, Case{21, kIpHardStop},
        Case{23, kIpAbort}}) {
    Axis axis;
    ASSERT_EQ(axis.set_input_logic(1, c.il), Status::kOk) << c.il;
    EXPECT_EQ(axis.input_port(), 0u) << c.il;
    axis.set_input_level(1, true);
    EXPECT_EQ(axis.input_port(), c.bit | level1) << c.il;
    ASSERT_EQ(axis.set_input_logic(1, c.il - 1), Status::kOk);  // the same function, active low
    EXPECT_EQ(axis.input_port(), level1) << c.il;
  }
  Axis axis;
  axis.set_input_logic(6, 7);
  axis.set_input_level(6, true);
  EXPECT_EQ(axis.input_port(), (kIpGeneralPurpose1 << 5) | (1u << (kIpLevelShift + 5)));
}

TEST(drive_status, SoftStopAndAbortStopTheMotionButAllowTheNext) {
  for (int32_t il : {15, 23}) {
    Axis axis;
    axis.set_input_logic(2, il);
    enable(axis);
    set_motion(axis, 20000, 1000000, 1000000);
    axis.parameters().stop_decel_counts_per_s2 = 400000;
    axis.set_jog_velocity(20000);
    axis.begin();
    run_us(axis, 100000);
    const double at = axis.reference_position_exact();
    axis.set_input_level(2, true);
    EXPECT_EQ(axis.step() & kEventHardStop, 0u) << il;  // no AUTO_STOP: not a hard stop
    run_us(axis, 100000);
    EXPECT_FALSE(axis.profiler_moving()) << il;
    EXPECT_NEAR(axis.reference_position_exact() - at, 500.0, 25.0) << il;  // v^2 / (2 SD)
    axis.begin();  // still active, but a new motion may start
    run_us(axis, 50000);
    EXPECT_TRUE(axis.profiler_moving()) << il;
  }
}

TEST(drive_status, IgnoredInputOnlyReportsItsLevel) {
  Axis axis;
  axis.set_input_logic(4, 5);
  axis.set_input_level(4, true);
  EXPECT_EQ(axis.step(), 0u);
  EXPECT_TRUE(axis.input_active(4));  // active by its polarity, yet it has no function
  EXPECT_EQ(axis.input_port(), 1u << (kIpLevelShift + 3));
}

TEST(drive_status, SpeedAndPositionFaultLimits) {
  {
    Axis axis;
    axis.parameters().speed_fault_high_counts_per_s = 30000;  // HL[2]
    enable(axis);
    set_motion(axis, 40000, 1000000, 1000000);
    axis.set_jog_velocity(40000);
    axis.begin();
    EXPECT_TRUE(run_us(axis, 100000) & kEventFault);
    EXPECT_EQ(axis.motor_fault(), static_cast<uint32_t>(kFaultSpeedLimit));
  }
  {
    Axis axis;
    axis.parameters().position_fault_high_counts = 5000;  // HL[3]
    enable(axis);
    start_move(axis);  // to 10000
    EXPECT_TRUE(run_us(axis, 300000) & kEventFault);
    EXPECT_EQ(axis.motor_fault(), static_cast<uint32_t>(kFaultPositionLimit));
  }
}

TEST(drive_status, PtMotionFollowsTheTableAndEndsAtItsLast) {
  Axis axis;
  enable(axis);
  PtTable& t = axis.pt_table();
  t.positions[0] = 0;     // QP[1]
  t.positions[1] = 1000;  // QP[2]
  t.positions[2] = 3000;
  t.positions[3] = 2000;
  t.positions[4] = 2000;  // a still last segment: the stop at the end is immediate
  t.first = 1;
  t.last = 5;
  t.cycles_per_point = 2000;  // 100 ms per point at TS=50 us: at most 20000 counts/s
  axis.set_pt_start(1);
  ASSERT_EQ(axis.begin(), Status::kOk);
  run_us(axis, 150000);  // 3000 cycles: half way from QP[2] to QP[3]
  EXPECT_NEAR(axis.reference_position_exact(), 2000.0, 1e-6);
  EXPECT_EQ(axis.pt_index(), 2);
  EXPECT_EQ(axis.motion_status(), 2);
  EXPECT_EQ(axis.motor_fault(), 0u);
  run_us(axis, 300000);
  EXPECT_FALSE(axis.profiler_moving());
  EXPECT_NEAR(axis.reference_position_exact(), 2000.0, 1e-6);
  EXPECT_EQ(axis.motion_status(), 1);  // "a completed PT motion": no longer 2
}

TEST(drive_status, PtMotionRefusedOutsideItsTableOrMode) {
  Axis axis;
  enable(axis);
  axis.pt_table().first = 2;
  axis.pt_table().last = 4;
  axis.set_pt_start(5);
  EXPECT_EQ(axis.begin(), Status::kBadStartData);
  axis.set_motor_on(false);
  ASSERT_EQ(axis.set_unit_mode(2), Status::kOk);
  enable(axis);
  axis.set_pt_start(2);
  EXPECT_EQ(axis.begin(), Status::kModeNotSupported);
}

TEST(drive_pt_table, SamplesCyclesAndEnds) {
  PtTable t;
  t.positions[0] = 0;
  t.positions[1] = 100;
  t.positions[2] = 300;
  t.first = 1;
  t.last = 3;
  t.cycles_per_point = 10;
  ASSERT_TRUE(pt_can_start(t, 1));
  EXPECT_FALSE(pt_can_start(t, 4));
  PtSample s = sample_pt(t, 1, 5, 0.001);
  EXPECT_DOUBLE_EQ(s.position_counts, 50.0);
  EXPECT_DOUBLE_EQ(s.velocity_counts_per_s, 100.0 / 0.01);
  EXPECT_EQ(s.index, 1);
  s = sample_pt(t, 1, 20, 0.001);
  EXPECT_TRUE(s.ended);
  EXPECT_DOUBLE_EQ(s.position_counts, 300.0);
  t.cyclic = true;
  s = sample_pt(t, 1, 25, 0.001);  // the segment from QP[3] back to QP[1]
  EXPECT_FALSE(s.ended);
  EXPECT_EQ(s.index, 3);
  EXPECT_DOUBLE_EQ(s.position_counts, 150.0);
  s = sample_pt(t, 2, 35, 0.001);  // started at 2: 2, 3, 1, then 2 again
  EXPECT_EQ(s.index, 2);
}

}  // namespace
}  // namespace uprog::drive
