// Gold's recorder commands on an axis: the ids recorder_commands.cpp uses are the table's, the
// refusals (ranges, busy, no signal) and the reports of RR and SR bits 16-17 through a recording.
#include <gtest/gtest.h>

#include "dialects/gold/commands.h"
#include "dialects/gold/drive_commands.h"
#include "dialects/gold/recorder_commands.h"

namespace uprog::gold {
namespace {

uint16_t id(const char* name) { return find_command(name)->id; }

TEST(gold_recorder_commands, IdsAreTheTablesAndServed) {
  EXPECT_EQ(id("RV"), 53);
  EXPECT_EQ(id("RL"), 54);
  EXPECT_EQ(id("RG"), 55);
  EXPECT_EQ(id("RR"), 56);
  EXPECT_EQ(id("RC"), 76);
  EXPECT_EQ(id("RP"), 77);
  EXPECT_EQ(id("WI"), 78);
  for (const char* n : {"RV", "RL", "RG", "RR", "RC", "RP", "WI"})
    EXPECT_TRUE(RecorderCommands::serves(id(n))) << n;
  EXPECT_FALSE(RecorderCommands::serves(id("PX")));
}

struct Fixture {
  drive::Axis axis;
  DriveCommands commands{axis};
  int32_t write(const char* name, int32_t index, int32_t v) {
    return commands.write(id(name), index, Value::of_int(v));
  }
  int32_t read(const char* name, int32_t index = 0) {
    Value v{};
    EXPECT_EQ(commands.read(id(name), index, v), kDriveOk) << name;
    return v.i;
  }
  uint32_t sr_recorder() { return (static_cast<uint32_t>(read("SR")) >> 16) & 3u; }
};

TEST(gold_recorder_commands, RangesAndRefusals) {
  Fixture f;
  EXPECT_EQ(f.read("RR"), -1);
  EXPECT_EQ(f.write("RR", 0, 2), kErrorRecorderNoSignals);  // RC = 0
  EXPECT_EQ(f.write("RV", 1, 12), kErrorOutOfRange);        // no signal 12
  EXPECT_EQ(f.write("RV", 1, 1023), kErrorOutOfRange);      // "a variable" needs DB##RV first
  EXPECT_EQ(f.write("RP", 1, 3), kErrorOutOfRange);         // two bits
  EXPECT_EQ(f.write("RP", 0, 2), kErrorOutOfRange);
  EXPECT_EQ(f.write("RP", 2, 101), kErrorOutOfRange);
  EXPECT_EQ(f.write("RP", 3, 7), kErrorOutOfRange);
  EXPECT_EQ(f.write("RP", 7, 64), kErrorOutOfRange);  // 6 inputs
  EXPECT_EQ(f.write("RG", 0, 4097), kErrorOutOfRange);
  EXPECT_EQ(f.write("RR", 0, 4), kErrorOutOfRange);
  EXPECT_EQ(f.write("RV", 2, 0), kDriveOk);
  EXPECT_EQ(f.write("RC", 0, 2), kDriveOk);
  EXPECT_EQ(f.write("RR", 0, 2), kErrorRecorderNoSignals);  // RC's bit 1 selects RV[2] = 0
  EXPECT_EQ(f.write("RV", 2, 1), kDriveOk);
  EXPECT_EQ(f.write("RP", 3, 2), kDriveOk);  // positive slope, but no RP[1]
  EXPECT_EQ(f.write("RR", 0, 3), kErrorRecorderNoSignals);
}

TEST(gold_recorder_commands, ImmediateRecordingReportsThroughRrAndSr) {
  Fixture f;
  ASSERT_EQ(f.write("RV", 1, 1), kDriveOk);
  ASSERT_EQ(f.write("RC", 0, 1), kDriveOk);
  ASSERT_EQ(f.write("RL", 0, 10), kDriveOk);
  ASSERT_EQ(f.write("RP", 0, 0), kDriveOk);  // the 4 TS quantum: 40 cycles for 10 samples
  ASSERT_EQ(f.write("RP", 2, 50), kDriveOk);
  ASSERT_EQ(f.write("RR", 0, 2), kDriveOk);
  EXPECT_EQ(f.read("RR"), 2);
  EXPECT_EQ(f.sr_recorder(), 2u);  // bit 17: armed
  // Samples every 4 cycles: 1, 5, ..., 17 the pre-trigger share; the immediate trigger fires at
  // 18, the trigger sample is the next sample cycle, 21; then 25, 29, 33, 37.
  for (int i = 0; i < 20; ++i) f.axis.step();
  EXPECT_EQ(f.sr_recorder(), 2u);  // still armed: the trigger sample is not taken yet
  f.axis.step();
  EXPECT_EQ(f.sr_recorder(), 3u);  // recording now
  EXPECT_EQ(f.write("RL", 0, 20), kErrorRecorderBusy);
  EXPECT_EQ(f.write("RP", 8, 3), kDriveOk);  // the upload range is no recorder setting
  for (int i = 0; i < 15; ++i) f.axis.step();
  EXPECT_EQ(f.sr_recorder(), 3u);
  f.axis.step();
  EXPECT_EQ(f.sr_recorder(), 1u);  // bit 16: done
  EXPECT_EQ(f.read("RR"), 0);
  const std::optional<drive::Recording> r = f.axis.recorder().recording(f.axis.period_us());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->samples(), 10u);
  EXPECT_EQ(r->sample_period_us, 200u);
  EXPECT_EQ(r->trigger_index, 5u);
  EXPECT_EQ(r->channels[0].name, "PX");
  EXPECT_EQ(f.write("RC", 0, 1), kDriveOk);  // "setting RC will invalidate this data"
  EXPECT_EQ(f.read("RR"), -1);
}

}  // namespace
}  // namespace uprog::gold
