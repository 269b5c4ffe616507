// Each trigger kind with a pre-trigger share on a scripted move: the trigger sample's index, its
// time and the values around it against the analytic trapezoid (a = 1e6 counts/s^2, TS = 50 us).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "drive/axis.h"
#include "drive/recorder.h"

namespace uprog::drive {
namespace {

constexpr double kAccel = 1e6;      // counts/s^2
constexpr double kSpeed = 50000.0;  // counts/s
constexpr double kTs = 50e-6;       // s

// The trapezoid's reference after motion step k (the profile at k * TS).
double analytic_position(int k) {
  const double t = k * kTs, ta = kSpeed / kAccel;
  return t <= ta ? 0.5 * kAccel * t * t : 0.5 * kAccel * ta * ta + kSpeed * (t - ta);
}
double analytic_velocity(int k) { return std::min(kAccel * k * kTs, kSpeed); }

struct Bench {
  Axis axis;
  Bench() {
    axis.set_motor_on(true);
    steps(500);  // past the enable delay
    axis.parameters().speed_counts_per_s = 50000;
    axis.parameters().accel_counts_per_s2 = 1000000;
    axis.parameters().decel_counts_per_s2 = 1000000;
  }
  void steps(int n) {
    for (int i = 0; i < n; ++i) axis.step();
  }
  void begin(int32_t target) {
    axis.set_absolute_target(target);
    ASSERT_EQ(axis.begin(), Status::kOk);
  }
  // Steps until the recorder is done (at most n cycles); the cycles it took.
  int until_done(int n) {
    for (int i = 1; i <= n; ++i) {
      axis.step();
      if (axis.recorder().state() == RecorderState::kDone) return i;
    }
    return -1;
  }
};

RecorderSettings profile_settings(uint32_t length, uint32_t pre, uint32_t gap, TriggerKind kind) {
  RecorderSettings s;
  s.channels = {signal_channel(Signal::kReferencePosition, "DV3"),
                signal_channel(Signal::kReferenceVelocity, "DV2")};
  s.length = length;
  s.pretrigger_percent = pre;
  s.gap_cycles = gap;
  s.trigger.kind = kind;
  return s;
}

TEST(recorder_trigger, ImmediateTakesLengthSamplesFromTheNextCycle) {
  Bench b;
  b.begin(100000);
  b.steps(100);
  const uint32_t t0 = b.axis.time_us();
  std::string why;
  ASSERT_TRUE(b.axis.recorder().arm(profile_settings(10, 0, 1, TriggerKind::kImmediate), &why))
      << why;
  EXPECT_EQ(b.axis.recorder().state(), RecorderState::kWaiting);
  EXPECT_EQ(b.until_done(100), 10);
  const std::optional<Recording> r = b.axis.recorder().recording(b.axis.period_us());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->samples(), 10u);
  EXPECT_EQ(r->trigger_index, 0u);
  EXPECT_EQ(r->trigger_time_us, t0 + 50u);
  EXPECT_EQ(r->sample_period_us, 50u);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(r->channels[0].values[i], analytic_position(101 + i), 1.0) << "sample " << i;
    EXPECT_NEAR(r->channels[1].values[i], analytic_velocity(101 + i), 1.0) << "sample " << i;
  }
}

TEST(recorder_trigger, BeginOfMotionWithTwentyPercentPretriggerAndGap) {
  Bench b;
  std::string why;
  ASSERT_TRUE(b.axis.recorder().arm(profile_settings(100, 20, 2, TriggerKind::kBeginMotion), &why))
      << why;
  EXPECT_EQ(b.axis.recorder().state(), RecorderState::kArmed);
  b.steps(39);  // samples at cycles 1, 3, ..., 39: 20 of them fill the pre-trigger share
  EXPECT_EQ(b.axis.recorder().state(), RecorderState::kWaiting);
  b.steps(1);  // cycle 40 takes none; cycle 41 is both the first motion step and a sample
  const uint32_t bg_time = b.axis.time_us();
  b.begin(100000);
  EXPECT_EQ(b.until_done(1000),
            159);  // 80 samples after the trigger, at motion steps 1, 3, ..., 159
  const std::optional<Recording> r = b.axis.recorder().recording(b.axis.period_us());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->samples(), 100u);
  EXPECT_EQ(r->trigger_index, 20u);
  EXPECT_EQ(r->sample_period_us, 100u);
  EXPECT_EQ(r->trigger_time_us, bg_time + 50u);
  EXPECT_EQ(r->time_us(0), -2000);
  for (int i = 0; i < 20; ++i)
    EXPECT_EQ(r->channels[0].values[i], 0.0) << "pre-trigger sample " << i;
  for (int j = 0; j < 80; ++j) {
    const int step = 1 + 2 * j;
    EXPECT_NEAR(r->channels[0].values[20 + j], analytic_position(step), 1.0) << "sample " << 20 + j;
    EXPECT_NEAR(r->channels[1].values[20 + j], analytic_velocity(step), 1.0) << "sample " << 20 + j;
  }
}

TEST(recorder_trigger, BeginOfMotionBeforeThePretriggerIsFullIsMissed) {
  Bench b;
  ASSERT_TRUE(
      b.axis.recorder().arm(profile_settings(100, 50, 1, TriggerKind::kBeginMotion), nullptr));
  b.steps(10);
  b.begin(100000);
  b.steps(200);
  EXPECT_EQ(b.axis.recorder().state(), RecorderState::kWaiting);
  EXPECT_FALSE(b.axis.recorder().recording(50));
  b.axis.recorder().kill();
  EXPECT_EQ(b.axis.recorder().state(), RecorderState::kIdle);
}

TEST(recorder_trigger, AnEarlyTriggerTakesTheSamplesThereAreWhenAllowed) {
  Bench b;
  RecorderSettings s = profile_settings(100, 50, 1, TriggerKind::kBeginMotion);
  s.early_trigger = true;
  ASSERT_TRUE(b.axis.recorder().arm(s, nullptr));
  b.steps(10);
  b.begin(100000);
  EXPECT_EQ(b.until_done(1000), 90);  // the length stays: 10 before, the trigger sample, 89 after
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->samples(), 100u);
  EXPECT_EQ(r->trigger_index, 10u);
  for (int j = 0; j < 90; ++j)
    EXPECT_NEAR(r->channels[0].values[10 + j], analytic_position(1 + j), 1.0);
}

// The trigger sample is the first at or past the level; the sample before it lies below.
TEST(recorder_trigger, RisingLevelOnTheReferenceVelocity) {
  Bench b;
  RecorderSettings s = profile_settings(200, 50, 1, TriggerKind::kRising);
  s.trigger.source = signal_channel(Signal::kReferenceVelocity, "DV2");
  s.trigger.level = 25000;
  ASSERT_TRUE(b.axis.recorder().arm(s, nullptr));
  b.steps(150);
  const uint32_t bg_time = b.axis.time_us();
  b.begin(100000);
  ASSERT_GT(b.until_done(2000), 0);
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->trigger_index, 100u);
  const int step = static_cast<int>(std::ceil(25000.0 / (kAccel * kTs) - 1e-9));  // 500
  EXPECT_EQ(r->trigger_time_us, bg_time + 50u * static_cast<uint32_t>(step));
  EXPECT_GE(r->channels[1].values[100], 25000.0);
  EXPECT_LT(r->channels[1].values[99], 25000.0);
  EXPECT_NEAR(r->channels[0].values[100], analytic_position(step), 1.0);
  EXPECT_NEAR(r->channels[0].values[0], analytic_position(step - 100), 1.0);
  EXPECT_EQ(r->trigger, "rising DV2 25000");
}

TEST(recorder_trigger, FallingLevelInTheDeceleration) {
  Bench b;
  RecorderSettings s = profile_settings(100, 10, 1, TriggerKind::kFalling);
  s.trigger.source = signal_channel(Signal::kReferenceVelocity, "DV2");
  s.trigger.level = 25000;
  ASSERT_TRUE(b.axis.recorder().arm(s, nullptr));
  b.steps(20);
  const uint32_t bg_time = b.axis.time_us();
  b.begin(100000);
  ASSERT_GT(b.until_done(50000), 0);
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->trigger_index, 10u);
  EXPECT_LE(r->channels[1].values[10], 25000.0);
  EXPECT_GT(r->channels[1].values[9], 25000.0);
  // The profile ends at 2.05 s; the velocity falls through half the speed 25 ms before.
  const double t = static_cast<double>(r->trigger_time_us - bg_time) * 1e-6;
  EXPECT_NEAR(t, 2.05 - 0.025, kTs);
}

TEST(recorder_trigger, LeavingAWindowAroundTheStart) {
  Bench b;
  RecorderSettings s = profile_settings(50, 20, 1, TriggerKind::kWindowLeave);
  s.trigger.source = signal_channel(Signal::kReferencePosition, "DV3");
  s.trigger.low = -100;
  s.trigger.level = 100;
  ASSERT_TRUE(b.axis.recorder().arm(s, nullptr));
  b.steps(30);
  const uint32_t bg_time = b.axis.time_us();
  b.begin(100000);
  ASSERT_GT(b.until_done(5000), 0);
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->trigger_index, 10u);
  // DV[3] is PX's whole counts: the first step whose 0.5 a t^2 rounds past 100.
  int step = 1;
  while (std::lround(analytic_position(step)) <= 100) ++step;
  EXPECT_EQ(step, 284);
  EXPECT_EQ(r->trigger_time_us - bg_time, 50u * static_cast<uint32_t>(step));
  EXPECT_GT(r->channels[0].values[10], 100.0);
  EXPECT_LE(r->channels[0].values[9], 100.0);
}

TEST(recorder_trigger, EnteringAWindowAroundTheTarget) {
  Bench b;
  RecorderSettings s = profile_settings(40, 25, 1, TriggerKind::kWindowEnter);
  s.trigger.source = signal_channel(Signal::kReferencePosition, "DV3");
  s.trigger.low = 99000;
  s.trigger.level = 101000;
  ASSERT_TRUE(b.axis.recorder().arm(s, nullptr));
  b.steps(20);
  const uint32_t bg_time = b.axis.time_us();
  b.begin(100000);
  ASSERT_GT(b.until_done(50000), 0);
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->trigger_index, 10u);
  EXPECT_GE(r->channels[0].values[10], 99000.0);
  EXPECT_LT(r->channels[0].values[9], 99000.0);
  // In the deceleration 1000 counts before the end: 0.5 a t^2 = 1000 at t = sqrt(2e-3) s
  // before 2.05 s.
  const double t = static_cast<double>(r->trigger_time_us - bg_time) * 1e-6;
  EXPECT_NEAR(t, 2.05 - std::sqrt(2.0 * 1000.0 / kAccel), kTs);
}

TEST(recorder_trigger, DigitalInputEdge) {
  Bench b;
  ASSERT_EQ(b.axis.set_input_logic(2, 7), Status::kOk);  // general purpose, active high
  RecorderSettings s = profile_settings(20, 50, 1, TriggerKind::kInput);
  s.channels.push_back(signal_channel(Signal::kInputPort, "IP"));
  s.trigger.input_mask = 0b10;
  s.trigger.input_polarity = 0b10;
  ASSERT_TRUE(b.axis.recorder().arm(s, nullptr));
  b.axis.set_input_level(2, true);  // active before the share is full: no trigger
  b.steps(30);
  b.axis.set_input_level(2, false);
  b.steps(5);
  EXPECT_EQ(b.axis.recorder().state(), RecorderState::kWaiting);
  const uint32_t edge_time = b.axis.time_us();
  b.axis.set_input_level(2, true);
  EXPECT_EQ(b.until_done(100), 10);
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->trigger_index, 10u);
  EXPECT_EQ(r->trigger_time_us, edge_time + 50u);
  const uint32_t before = static_cast<uint32_t>(r->channels[2].values[9]);
  const uint32_t at = static_cast<uint32_t>(r->channels[2].values[10]);
  EXPECT_NE(before, at);  // the port's level bit of input 2 changed at the trigger sample
}

class FakeWords final : public ProgramWords {
 public:
  std::optional<Word> find_global(std::string_view name, uint32_t element) const override {
    if (name == "speeds" && element < 3) return Word{1 + element, true};
    if (name == "cnt" && element == 0) return Word{0, false};
    return std::nullopt;
  }
  std::span<const Value> memory() const override { return words; }
  Value words[4] = {};
};

TEST(recorder_trigger, ProgramGlobalsAsChannelAndTriggerSource) {
  Bench b;
  FakeWords words;
  b.axis.recorder().set_program_words(&words);
  std::string why;
  const std::optional<Channel> cnt = global_channel(words, "cnt", &why);
  const std::optional<Channel> speed = global_channel(words, "speeds[2]", &why);
  ASSERT_TRUE(cnt && speed) << why;
  EXPECT_FALSE(global_channel(words, "speeds[3]", &why));
  EXPECT_EQ(why, "'speeds[3]' is no signal and no global of the program");
  EXPECT_FALSE(global_channel(words, "speeds[x]", &why));
  RecorderSettings s;
  s.channels = {*cnt, *speed};
  s.length = 6;
  s.pretrigger_percent = 50;
  s.trigger.kind = TriggerKind::kRising;
  s.trigger.source = *cnt;
  s.trigger.level = 5;
  ASSERT_TRUE(b.axis.recorder().arm(s, &why)) << why;
  for (int32_t i = 0; i < 20; ++i) {
    words.words[0] = Value::of_int(i);
    const float f = 0.5f * static_cast<float>(i);
    words.words[3] = Value::of_float(f);
    b.axis.step();
  }
  const std::optional<Recording> r = b.axis.recorder().recording(50);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->samples(), 6u);
  EXPECT_EQ(r->trigger_index, 3u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(r->channels[0].values[static_cast<size_t>(i)], 2 + i);
    EXPECT_EQ(r->channels[1].values[static_cast<size_t>(i)], 0.5 * (2 + i));
  }
  EXPECT_TRUE(r->channels[1].is_float);
}

}  // namespace
}  // namespace uprog::drive
