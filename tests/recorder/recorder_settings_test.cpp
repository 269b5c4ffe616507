// The recorder refuses unusable settings with a reason, takes its memory when armed and keeps
// a complete recording until it is armed again or invalidated.
#include <gtest/gtest.h>

#include "drive/axis.h"
#include "drive/recorder.h"

namespace uprog::drive {
namespace {

RecorderSettings one_channel() {
  RecorderSettings s;
  s.channels = {signal_channel(Signal::kPosition, "PX")};
  s.length = 8;
  return s;
}

TEST(recorder_settings, RefusesWhatCannotBeRecorded) {
  Recorder r;
  std::string why;
  RecorderSettings s = one_channel();
  s.channels.clear();
  EXPECT_FALSE(r.arm(s, &why));
  EXPECT_EQ(why, "the recorder needs at least one channel");
  s = one_channel();
  s.length = 0;
  EXPECT_FALSE(r.arm(s, &why));
  EXPECT_EQ(why, "the recording length is at least one sample");
  s = one_channel();
  s.gap_cycles = 0;
  EXPECT_FALSE(r.arm(s, &why));
  s = one_channel();
  s.pretrigger_percent = 101;
  EXPECT_FALSE(r.arm(s, &why));
  EXPECT_EQ(why, "the pre-trigger share is 0..100 percent");
  s = one_channel();
  s.channels.assign(17, signal_channel(Signal::kPosition, "PX"));
  EXPECT_FALSE(r.arm(s, &why));
  s = one_channel();
  s.channels.assign(8, signal_channel(Signal::kPosition, "PX"));
  s.length = static_cast<uint32_t>(kMaxRecorderWords / 8 + 1);
  EXPECT_FALSE(r.arm(s, &why));
  EXPECT_EQ(why, "the recording does not fit the recorder's memory (4194304 words)");
  EXPECT_EQ(r.state(), RecorderState::kIdle);
}

TEST(recorder_settings, HundredPercentPretriggerKeepsTheTriggerSample) {
  Axis axis;
  RecorderSettings s = one_channel();
  s.pretrigger_percent = 100;
  ASSERT_TRUE(axis.recorder().arm(s, nullptr));
  for (int i = 0; i < 20; ++i) axis.step();
  const std::optional<Recording> r = axis.recorder().recording(axis.period_us());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->samples(), 8u);
  EXPECT_EQ(r->trigger_index, 7u);
  EXPECT_EQ(axis.recorder().state(), RecorderState::kDone);
}

TEST(recorder_settings, DoneStaysUntilInvalidatedAndKillDropsAnActiveOne) {
  Axis axis;
  ASSERT_TRUE(axis.recorder().arm(one_channel(), nullptr));
  for (int i = 0; i < 4; ++i) axis.step();
  EXPECT_EQ(axis.recorder().state(), RecorderState::kTriggered);
  EXPECT_EQ(axis.recorder().samples_recorded(), 4u);
  ASSERT_TRUE(axis.recorder().recording(50));  // partial, while recording
  EXPECT_EQ(axis.recorder().recording(50)->samples(), 4u);
  axis.recorder().kill();
  EXPECT_EQ(axis.recorder().state(), RecorderState::kIdle);
  ASSERT_TRUE(axis.recorder().arm(one_channel(), nullptr));
  for (int i = 0; i < 20; ++i) axis.step();
  EXPECT_EQ(axis.recorder().state(), RecorderState::kDone);
  axis.recorder().kill();  // a complete recording survives a kill (RR=0)
  EXPECT_EQ(axis.recorder().state(), RecorderState::kDone);
  axis.recorder().invalidate();
  EXPECT_FALSE(axis.recorder().recording(50));
}

}  // namespace
}  // namespace uprog::drive
