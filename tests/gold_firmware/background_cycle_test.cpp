// The Gold background pass (manual 2.2, dialects/gold/background_cycle.h): inside the manual's
// 100 µs .. 1 ms for every TS the drive takes, shorter as TS grows, a fixed pass when the user
// gives one (the options, the transcripts' `background` directive), and TS changed on the
// command line paces the program from then on.
#include "dialects/gold/background_cycle.h"

#include <gtest/gtest.h>

#include "drive/axis.h"
#include "gold_drive.h"

namespace uprog::controller {
namespace {

// Manual 2.2: "can jitter between 100 µsec and 1 msec"; "A higher sampling time means faster
// user program execution".
TEST(GoldBackground, EveryServoPeriodGivesAPassInTheManualsRangeShorterAsTsGrows) {
  uint64_t previous = gold::background_pass_ns(drive::kMinPeriod_us);
  EXPECT_EQ(previous, 1'000'000u);  // the manual's slowest at the shortest TS
  for (uint32_t ts = drive::kMinPeriod_us; ts <= drive::kMaxPeriod_us; ++ts) {
    const uint64_t pass = gold::background_pass_ns(ts);
    EXPECT_GE(pass, 100'000u) << "TS " << ts;
    EXPECT_LE(pass, 1'000'000u) << "TS " << ts;
    EXPECT_LE(pass, previous) << "TS " << ts;
    previous = pass;
  }
  // 200 µs · TS / (2 · TS − 45 µs), rounded down to whole ns.
  EXPECT_EQ(gold::background_pass_ns(50), 181'818u);          // 10 000 000 / 55
  EXPECT_EQ(gold::background_pass_ns(100), 129'032u);         // 20 000 000 / 155
  EXPECT_EQ(gold::background_pass_ns(2000), 101'137u);        // 400 000 000 / 3955
  EXPECT_EQ(gold::background_pass_ns(50, 1000), 1'000'000u);  // fixed by the user
}

TEST(GoldBackground, TheFirmwareCycleIsThePassAndFollowsTs) {
  Controller c(gold_options());
  EXPECT_EQ(c.firmware().cycle_ns(), 181'818u);
  ASSERT_TRUE(c.send("TS=100").empty());
  EXPECT_EQ(c.firmware().cycle_ns(), 129'032u);
}

TEST(GoldBackground, TheOptionAndTheDirectiveFixThePass) {
  ControllerOptions o = gold_options();
  o.timing.background_us = 500;
  Controller c(o);
  EXPECT_EQ(c.firmware().cycle_ns(), 500'000u);
  std::string failure;
  EXPECT_TRUE(c.firmware().world_directive("background", "auto", failure));
  EXPECT_EQ(failure, "");
  EXPECT_EQ(c.firmware().cycle_ns(), 181'818u);
  EXPECT_TRUE(c.firmware().world_directive("background", "250us", failure));
  EXPECT_EQ(c.firmware().cycle_ns(), 250'000u);
  EXPECT_TRUE(c.firmware().world_directive("background", "300", failure));
  EXPECT_EQ(c.firmware().cycle_ns(), 300'000u);
  for (const char* bad : {"0", "0us", "1000001us", "-5", "fast", "5ms", ""}) {
    failure.clear();
    EXPECT_TRUE(c.firmware().world_directive("background", bad, failure)) << bad;
    EXPECT_EQ(failure, "background takes 'auto' or 1..1000000us") << bad;
    EXPECT_EQ(c.firmware().cycle_ns(), 300'000u) << bad;  // a refused one changes nothing
  }
  EXPECT_FALSE(c.firmware().world_directive("analog", "5", failure));  // not Gold's
}

// An expression on the command line still takes one servo cycle (gold-command-line.md).
TEST(GoldBackground, AnExpressionStillTakesOneServoCycle) {
  Controller c(gold_options());
  const uint64_t t0 = c.now_us();
  c.send("PX");
  EXPECT_EQ(c.now_us() - t0, 50u);
}

}  // namespace
}  // namespace uprog::controller
