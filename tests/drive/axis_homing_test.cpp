// Homing and capture on the axis: each home event (at once, a home switch, a limit, an input's
// release, the index pulse, the index after the switch), each action and position setting, and
// the index-crossing test.
#include <gtest/gtest.h>

#include "axis_helpers.h"
#include "drive/axis.h"
#include "drive/events.h"
#include "drive/homing.h"
#include "drive/inputs.h"

namespace uprog::drive {
namespace {

using testing::enable;
using testing::run_us;
using testing::set_motion;

constexpr int kHomeInput = 5;

// Steps until the home event (or `max_us`); returns the events of the cycle it came in.
uint32_t run_until_home(Axis& axis, uint64_t max_us) {
  for (uint64_t t = 0; t < max_us; t += axis.period_us()) {
    const uint32_t e = axis.step();
    if (e & kEventHome) return e;
  }
  return 0;
}

void jog(Axis& axis, int32_t velocity) {
  set_motion(axis, 100000, 1000000, 1000000);
  axis.set_jog_velocity(velocity);
  ASSERT_EQ(axis.begin(), Status::kOk);
}

TEST(drive_homing, ImmediateEventSetsTheHomeValueAtOnce) {
  Axis axis;
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kImmediate;
  h.setting = HomePositionSetting::kAbsolute;
  h.home_value_counts = 5000;
  axis.arm_homing(true);
  EXPECT_TRUE(axis.homing_armed());
  EXPECT_EQ(axis.status_register() & kSrHoming, kSrHoming);
  EXPECT_EQ(axis.step() & kEventHome, static_cast<uint32_t>(kEventHome));
  EXPECT_FALSE(axis.homing_armed());  // HM[1] reads 0 once the event came
  EXPECT_EQ(axis.status_register() & kSrHoming, 0u);
  EXPECT_EQ(axis.home_capture(), 0);
  EXPECT_EQ(axis.position(), 5000);
  EXPECT_EQ(axis.step() & kEventHome, 0u);  // one event per arming
}

TEST(drive_homing, HomeSwitchStopsWithSdAndSetsPosition) {
  Axis axis;
  ASSERT_EQ(axis.set_input_logic(kHomeInput, 17), Status::kOk);  // main home, active high
  axis.place_position_switch(kHomeInput, 20000.0, 30000.0);
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kHomeInput;
  h.action = HomeAction::kStop;
  h.setting = HomePositionSetting::kAbsolute;
  h.home_value_counts = 0;
  axis.arm_homing(true);
  jog(axis, 10000);
  ASSERT_NE(run_until_home(axis, 3000000), 0u);
  // The switch closes at 20000; the level is read at the next cycle start (0.5 count a cycle).
  EXPECT_NEAR(axis.home_capture(), 20000, 2);
  EXPECT_EQ(axis.home_event_count(), 1u);
  EXPECT_EQ(axis.input_port() & kIpMainHome, kIpMainHome);
  run_us(axis, 100000);
  EXPECT_FALSE(axis.profiler_moving());
  // PX was 0 at the event; the stop with SD = 1e6 adds v^2 / (2 SD) = 50 counts.
  EXPECT_NEAR(axis.position(), 50, 3);
  EXPECT_EQ(axis.motion_status(), 1);  // stopped, not at a point-to-point target
}

TEST(drive_homing, ReverseLimitIsTheHomeSwitch) {
  Axis axis;
  ASSERT_EQ(axis.set_input_logic(1, 9), Status::kOk);  // reverse limit, active high
  axis.place_position_switch(1, -1000000.0, -2000.0);
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kHomeInput;
  h.home_switch = HomeSwitch::kMainHome;  // no main-home input: the limit is not the event
  axis.arm_homing(true);
  jog(axis, -10000);
  EXPECT_EQ(run_until_home(axis, 400000), 0u);
  EXPECT_TRUE(axis.homing_armed());
  // Off the limit again, then armed on the reverse limit itself: its edge is the event.
  axis.set_absolute_target(0);
  ASSERT_EQ(axis.begin(), Status::kOk);
  run_us(axis, 500000);
  h.home_switch = HomeSwitch::kReverseLimit;
  h.home_value_counts = -100;
  jog(axis, -10000);
  ASSERT_NE(run_until_home(axis, 1000000), 0u);
  EXPECT_NEAR(axis.home_capture(), -2000, 2);
  EXPECT_NEAR(axis.position(), -100, 1);  // PX := HM[2] where the limit rose
}

TEST(drive_homing, AnInputsReleaseIsTheEventWhateverItsFunction) {
  Axis axis;
  axis.place_position_switch(3, 1000.0, 3000.0);  // input 3 stays general purpose (IL 7)
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kHomeInput;
  h.home_switch = HomeSwitch::kInput;
  h.input = 3;
  h.on_release = true;
  h.action = HomeAction::kContinue;
  h.setting = HomePositionSetting::kKeep;
  axis.arm_homing(true);
  jog(axis, 20000);
  ASSERT_NE(run_until_home(axis, 1000000), 0u);
  EXPECT_NEAR(axis.home_capture(), 3000, 2);  // the far edge, not the near one at 1000
  EXPECT_TRUE(axis.profiler_moving());        // kContinue: the jog goes on
}

TEST(drive_homing, IndexCapturesExactlyAndRelativeSettingKeepsTheDistance) {
  Axis axis;
  ASSERT_EQ(axis.set_counts_per_revolution(4000), Status::kOk);
  axis.place_index_pulse(1000.0);  // pulses at 1000, 5000, 9000, ... motor counts
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kIndex;
  h.action = HomeAction::kContinue;
  h.setting = HomePositionSetting::kRelative;
  h.home_value_counts = 100;
  axis.arm_homing(true);
  jog(axis, 20000);
  ASSERT_NE(run_until_home(axis, 1000000), 0u);
  EXPECT_EQ(axis.home_capture(), 1000);  // the pulse's own position, not the cycle's
  // The index point is now 100: PX = motor position - 1000 + 100.
  EXPECT_NEAR(axis.position(), axis.motor_state().position_counts - 900.0, 1.0);
  EXPECT_TRUE(axis.profiler_moving());  // HM[4]=2: the motion continues
}

TEST(drive_homing, SwitchThenIndexTakesTheFirstIndexAfterTheSwitch) {
  Axis axis;
  ASSERT_EQ(axis.set_input_logic(kHomeInput, 17), Status::kOk);
  ASSERT_EQ(axis.set_counts_per_revolution(4000), Status::kOk);
  axis.place_index_pulse(1000.0);
  axis.place_position_switch(kHomeInput, 3000.0, 1e9);
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kHomeInputThenIndex;
  h.action = HomeAction::kStop;
  h.setting = HomePositionSetting::kAbsolute;
  h.home_value_counts = -7;
  axis.arm_homing(true);
  jog(axis, 20000);
  uint32_t homes = 0;
  for (int k = 0; k < 20000 && axis.homing_armed(); ++k)
    homes += (axis.step() & kEventHome) ? 1 : 0;
  EXPECT_EQ(homes, 1u);  // the switch alone is not the event while the process is armed
  EXPECT_EQ(axis.home_capture(), 5000);  // 1000 came before the switch (3000): ignored
  EXPECT_NEAR(axis.position(), -7, 2);
}

TEST(drive_homing, SetOutputActionAndKeepSetting) {
  Axis axis;
  enable(axis);
  HomingSettings& h = axis.homing_settings();
  h.trigger = HomeTrigger::kImmediate;
  h.action = HomeAction::kSetOutput;
  h.output = 2;
  h.setting = HomePositionSetting::kKeep;
  h.home_value_counts = 999;
  axis.set_position(42);
  axis.arm_homing(true);
  axis.step();
  EXPECT_TRUE(axis.output(2));
  EXPECT_FALSE(axis.output(1));
  EXPECT_EQ(axis.position(), 42);
  EXPECT_EQ(axis.home_capture(), 42);
}

TEST(drive_homing, DisarmedProcessTakesNoIndex) {
  Axis axis;
  ASSERT_EQ(axis.set_counts_per_revolution(4000), Status::kOk);
  enable(axis);
  axis.homing_settings().trigger = HomeTrigger::kIndex;
  axis.arm_homing(true);
  axis.arm_homing(false);
  jog(axis, 20000);
  EXPECT_EQ(run_us(axis, 500000) & kEventHome, 0u);  // 10000 counts: two pulses passed
  EXPECT_EQ(axis.home_event_count(), 0u);
}

TEST(drive_homing, UnarmedHomeInputIsTheGoldManualsHomeEvent) {
  // Manual 2.14.9: AUTO_HM when a main-home input becomes active, homing armed or not.
  Axis axis;
  axis.set_input_logic(kHomeInput, 16);  // active low
  axis.set_input_level(kHomeInput, true);
  axis.step();
  axis.set_input_level(kHomeInput, false);
  EXPECT_EQ(axis.step(), static_cast<uint32_t>(kEventHome));
  EXPECT_EQ(axis.home_event_count(), 0u);  // nothing captured, nothing set
}

TEST(drive_homing, PositionSwitchFollowsTheMotorUntilTheScenarioTakesTheInput) {
  Axis axis;
  axis.place_position_switch(2, -10.0, 10.0);
  EXPECT_TRUE(axis.input_level(2));  // the motor stands at 0
  axis.place_position_switch(3, 100.0, 200.0);
  EXPECT_FALSE(axis.input_level(3));
  axis.set_input_level(2, false);  // the scenario drives it now
  axis.step();
  EXPECT_FALSE(axis.input_level(2));
}

TEST(drive_homing, IndexCrossing) {
  // Pulses at 1000 + k * 4000.
  EXPECT_EQ(index_crossed(1000, 4000, 900, 1100), 1000.0);
  EXPECT_EQ(index_crossed(1000, 4000, 1100, 900), 1000.0);
  EXPECT_EQ(index_crossed(1000, 4000, 900, 1000), 1000.0);          // `to` counts
  EXPECT_FALSE(index_crossed(1000, 4000, 1000, 1100).has_value());  // `from` does not
  EXPECT_FALSE(index_crossed(1000, 4000, 1100, 4900).has_value());
  EXPECT_EQ(index_crossed(1000, 4000, -3100, -2900), -3000.0);
  EXPECT_EQ(index_crossed(1000, 4000, 0, 10000), 1000.0);  // several: the first
  EXPECT_EQ(index_crossed(1000, 4000, 10000, 0), 9000.0);
  EXPECT_FALSE(index_crossed(1000, 0, 0, 10000).has_value());  // no period, no pulse
  EXPECT_FALSE(index_crossed(1000, 4000, 500, 500).has_value());
}

}  // namespace
}  // namespace uprog::drive
