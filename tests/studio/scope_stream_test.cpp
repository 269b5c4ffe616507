// The live scope (scope_stream.h) through the studio's drive: every servo cycle's sample of every
// channel reaches the page, in time order with no gap, whatever the speed.
#include "studio/scope_stream.h"

#include <gtest/gtest.h>

#include "dialects/registry.h"
#include "drive/axis.h"
#include "page_recorder.h"
#include "support/files.h"

namespace uprog::studio {
namespace {

using nlohmann::json;
using testing::PageRecorder;

constexpr uint64_t kMs = 1'000'000;  // ns

struct Scope {
  Scope()
      : source(*read_text_file(std::string(UPROG_SOURCE_DIR) + "/examples/gold/first_move.ehl")),
        drive(StudioDriveOptions{dialects::find("gold"), "first_move.ehl", source, 0}) {
    page = drive.connect(recorder.sink());
  }
  void send(const json& m) { drive.handle(page, m.dump()); }
  std::string source;
  PageRecorder recorder;
  StudioDrive drive;
  uint64_t page = 0;
};

// Samples, channel by channel, of all blocks; checks that each block starts where the last ended.
std::vector<std::vector<double>> joined(const std::vector<ScopeBlock>& blocks) {
  std::vector<std::vector<double>> out;
  uint64_t next_us = blocks.empty() ? 0 : blocks.front().first_time_us;
  for (const ScopeBlock& b : blocks) {
    EXPECT_EQ(b.first_time_us, next_us);
    next_us = b.first_time_us + b.samples() * b.period_us;
    out.resize(b.channels);
    for (size_t i = 0; i < b.samples(); ++i) {
      for (size_t c = 0; c < b.channels; ++c) out[c].push_back(b.values[i * b.channels + c]);
    }
  }
  return out;
}

TEST(ScopeStream, EveryServoCycleOfEightChannelsWithoutAGap) {
  Scope s;
  s.send({{"op", "build"}, {"source", s.source}});
  s.send({{"op", "start"}});
  const std::vector<std::string> names = {"PX", "VX", "PE", "DV[3]", "DV[2]", "IQ", "MS", "moves"};
  s.send({{"op", "scope"}, {"channels", names}});
  const json scope = s.recorder.last("scope");
  ASSERT_EQ(scope["channels"].size(), 8u) << s.recorder.messages.back().dump();
  EXPECT_EQ(scope["channels"][0]["name"], "PX");
  const uint32_t period_us = s.drive.controller().axis().period_us();
  EXPECT_EQ(scope["period_us"], period_us);
  const uint64_t start_us = s.drive.controller().now_us();  // the lines above take time
  // 3 s at the wall clock, then 3 s more at x10 in 10 ms ticks: one sample a servo cycle.
  for (int i = 0; i < 300; ++i) s.drive.tick(10 * kMs);
  s.send({{"op", "speed"}, {"factor", 10}});
  for (int i = 0; i < 30; ++i) s.drive.tick(10 * kMs);
  const auto channels = joined(s.recorder.blocks);
  ASSERT_EQ(channels.size(), 8u);
  EXPECT_EQ(channels[0].size(), 6'000'000u / period_us);
  // The first sample is the first servo cycle's after the scope started.
  EXPECT_EQ(s.recorder.blocks.front().first_time_us, start_us + period_us);
  // first_move.txt: the move ends at 100000 counts, and moves counts 1.
  EXPECT_NEAR(channels[0].back(), 100000.0, 2.0);
  EXPECT_EQ(channels[0].front(), 0.0);
  EXPECT_EQ(channels[7].front(), 0.0);
  EXPECT_EQ(channels[7].back(), 1.0);
}

TEST(ScopeStream, AChannelThatIsNoneOrTooManyIsRefusedAndTheOldOnesStay) {
  Scope s;
  s.send({{"op", "scope"}, {"channels", {"PX"}}});
  s.send({{"op", "scope"}, {"channels", {"PX", "nosuchthing"}}});
  EXPECT_EQ(s.recorder.messages.back()["type"], "error");
  s.send({{"op", "scope"}, {"channels", std::vector<std::string>(9, "PX")}});
  EXPECT_EQ(s.recorder.messages.back()["type"], "error");
  s.drive.tick(10 * kMs);
  ASSERT_EQ(s.recorder.blocks.size(), 1u);
  EXPECT_EQ(s.recorder.blocks[0].channels, 1u);
  // No channels: the scope stops sending.
  s.send({{"op", "scope"}, {"channels", json::array()}});
  s.drive.tick(10 * kMs);
  EXPECT_EQ(s.recorder.blocks.size(), 1u);
}

TEST(ScopeStream, PausedTimeSendsNothing) {
  Scope s;
  s.send({{"op", "scope"}, {"channels", {"PX"}}});
  s.send({{"op", "speed"}, {"factor", 0}});
  s.drive.tick(10 * kMs);
  EXPECT_TRUE(s.recorder.blocks.empty());
}

}  // namespace
}  // namespace uprog::studio
