// The studio's drive through its page messages (studio_drive.h), in process: build and run, the
// terminal, pacing, inputs, faults, stop and reset, and hostile messages, in every dialect.
#include "studio/studio_drive.h"

#include <gtest/gtest.h>

#include "dialect/dl_lines.h"
#include "dialects/registry.h"
#include "drive/faults.h"
#include "page_recorder.h"
#include "support/files.h"

namespace uprog::studio {
namespace {

using nlohmann::json;
using testing::PageRecorder;

constexpr uint64_t kMs = 1'000'000;  // ns

std::string example(const std::string& name) {
  return *read_text_file(std::string(UPROG_SOURCE_DIR) + "/examples/" + name);
}

struct Studio {
  explicit Studio(const std::string& dialect_name, const std::string& file = "",
                  const std::string& source = "")
      : drive(StudioDriveOptions{dialects::find(dialect_name), file, source, 0}) {
    page = drive.connect(recorder.sink());
  }
  json request(const json& message) {
    drive.handle(page, message.dump());
    return recorder.messages.back();
  }
  // The terminal's answer texts to `line` (errors as "?code").
  std::vector<std::string> line(const std::string& text) {
    request({{"op", "line"}, {"text", text}});
    std::vector<std::string> out;
    const json answers = recorder.last("answers");
    for (const json& a : answers["answers"]) {
      out.push_back(a["error"] != 0 ? "?" + a["error"].dump() : a["text"].get<std::string>());
    }
    return out;
  }
  // `wall_ns` of wall time in 10 ms ticks, as StudioApp's timer gives it.
  void run_for(uint64_t wall_ns) {
    for (uint64_t t = 0; t < wall_ns; t += 10 * kMs) drive.tick(10 * kMs);
  }
  PageRecorder recorder;
  StudioDrive drive;
  uint64_t page = 0;
};

TEST(StudioDrive, HelloNamesTheProgramAndTheDrivesControls) {
  const std::string source = example("gold/first_move.ehl");
  Studio s("gold", "first_move.ehl", source);
  const json hello = s.recorder.messages.at(0);
  EXPECT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["dialect"], "gold");
  EXPECT_EQ(hello["file"], "first_move.ehl");
  EXPECT_EQ(hello["source"], source);
  EXPECT_EQ(hello["inputs"], 6);  // drive/parameters.h: inputs 1..6
  EXPECT_NE(std::find(hello["faults"].begin(), hello["faults"].end(), "overcurrent"),
            hello["faults"].end());
  EXPECT_EQ(s.recorder.messages.at(1)["type"], "status");
}

// examples/gold/first_move.txt: after 1 s moves is 0 and MS 2; after 3 s PS 0 and moves 1.
TEST(StudioDrive, BuildAndRunFirstMoveAtTheWallClock) {
  Studio s("gold", "first_move.ehl", example("gold/first_move.ehl"));
  const json built = s.request({{"op", "build"}, {"source", example("gold/first_move.ehl")}});
  EXPECT_EQ(s.recorder.last("build")["ok"], true) << built.dump();
  s.request({{"op", "start"}});
  EXPECT_EQ(s.recorder.last("started")["ok"], true);
  const uint64_t started_us = s.drive.controller().now_us();  // after the line's own time
  s.run_for(1000 * kMs);
  EXPECT_EQ(s.drive.controller().now_us(), started_us + 1'000'000u);
  EXPECT_EQ(s.line("moves"), std::vector<std::string>{"0"});
  EXPECT_EQ(s.line("MS"), std::vector<std::string>{"2"});
  s.run_for(2000 * kMs);
  EXPECT_EQ(s.line("PS"), std::vector<std::string>{"0"});
  EXPECT_EQ(s.line("moves"), std::vector<std::string>{"1"});
  EXPECT_EQ(s.line("abs(PX-100000)<=2"), std::vector<std::string>{"1"});
}

TEST(StudioDrive, SpeedPausesSlowsAndHurries) {
  Studio s("gold");
  s.request({{"op", "speed"}, {"factor", 0}});
  s.run_for(100 * kMs);
  EXPECT_EQ(s.drive.controller().now_us(), 0u);
  s.request({{"op", "speed"}, {"factor", 10}});
  s.run_for(100 * kMs);
  EXPECT_EQ(s.drive.controller().now_us(), 1'000'000u);
  s.request({{"op", "speed"}, {"factor", 0.1}});
  s.run_for(100 * kMs);
  EXPECT_EQ(s.drive.controller().now_us(), 1'010'000u);
  s.request({{"op", "speed"}, {"factor", "max"}});
  s.drive.tick(0);  // as fast as it goes: a fixed step a tick, whatever the wall says
  EXPECT_EQ(s.drive.controller().now_us(), 1'010'000u + StudioDrive::kMaxSpeedStepNs / 1000);
  for (const json& bad : {json(11), json(0.05), json(-1), json("fast")}) {
    EXPECT_EQ(s.request({{"op", "speed"}, {"factor", bad}})["type"], "error") << bad;
  }
  EXPECT_EQ(s.drive.speed(), StudioDrive::kMaxSpeed);
}

// Every dialect's sample program (dialect.h, SampleProgram): built, run from the page, its query
// answers what the dialect says once the program has done its work; Stop stops it.
TEST(StudioDrive, EveryDialectBuildsRunsAndStops) {
  for (const dialect::Dialect* d : dialects::all()) {
    SCOPED_TRACE(std::string(d->name()));
    const dialect::SampleProgram& sample = d->sample_program();
    Studio s(std::string(d->name()), std::string(sample.file_name), std::string(sample.source));
    s.request({{"op", "build"}, {"source", sample.source}});
    ASSERT_EQ(s.recorder.last("build")["ok"], true) << s.recorder.last("build").dump();
    if (sample.entry.empty()) {
      s.request({{"op", "start"}});
      EXPECT_EQ(s.recorder.last("started")["ok"], true) << s.recorder.last("started").dump();
    } else {
      ASSERT_EQ(s.drive.controller().start_program(sample.entry), "");
    }
    s.run_for(200 * kMs);
    EXPECT_EQ(s.line(std::string(sample.query)),
              std::vector<std::string>{std::string(sample.answer)});
    s.request({{"op", "stop"}});
    s.run_for(20 * kMs);
    EXPECT_EQ(s.drive.controller().program_running(), false);
    EXPECT_EQ(s.recorder.last("status")["running"], false);
  }
}

TEST(StudioDrive, ABrokenBuildNamesItsLineAndKeepsTheStoredProgram) {
  for (const dialect::Dialect* d : dialects::all()) {
    SCOPED_TRACE(std::string(d->name()));
    const dialect::SampleProgram& sample = d->sample_program();
    Studio s(std::string(d->name()), std::string(sample.file_name), std::string(sample.source));
    s.request({{"op", "build"}, {"source", sample.source}});
    ASSERT_EQ(s.recorder.last("build")["ok"], true);
    s.request({{"op", "build"}, {"source", sample.bad_source}, {"run", true}});
    const json build = s.recorder.last("build");
    EXPECT_EQ(build["ok"], false);
    ASSERT_FALSE(build["diagnostics"].empty());
    EXPECT_EQ(build["diagnostics"][0]["line"], sample.bad_source_line);
    EXPECT_EQ(build["diagnostics"][0]["severity"], "error");
    EXPECT_EQ(s.recorder.last("started"), nullptr);  // a failed build runs nothing
    if (sample.entry.empty()) {
      s.request({{"op", "start"}});
    } else {
      ASSERT_EQ(s.drive.controller().start_program(sample.entry), "");
    }
    s.run_for(200 * kMs);
    EXPECT_EQ(s.line(std::string(sample.query)),
              std::vector<std::string>{std::string(sample.answer)});
  }
}

// Manual 2.14.8 (examples/gold/2_14_auto_inputs.txt): input 2 sets UI[1]=9000 through AUTO_I2
// and main moves there: within 1.5 s PX is 9000 and UI[1] is 0 again.
TEST(StudioDrive, AnInputToggleRunsItsAutoRoutine) {
  const std::string source = example("gold/2_14_auto_inputs.ehl");
  Studio s("gold", "2_14_auto_inputs.ehl", source);
  s.request({{"op", "build"}, {"source", source}});
  s.request({{"op", "start"}});
  s.run_for(10 * kMs);
  EXPECT_EQ(s.request({{"op", "input"}, {"n", 2}, {"high", true}})["high"], true);
  s.run_for(10 * kMs);
  s.request({{"op", "input"}, {"n", 2}, {"high", false}});
  s.run_for(1500 * kMs);
  EXPECT_EQ(s.line("abs(PX-9000)<=2"), std::vector<std::string>{"1"});
  EXPECT_EQ(s.line("UI[1]"), std::vector<std::string>{"0"});
  s.drive.broadcast_status();
  EXPECT_EQ(s.recorder.last("status")["inputs"][1], false);
  EXPECT_EQ(s.request({{"op", "input"}, {"n", 7}, {"high", true}})["type"], "error");
}

// A switch placed on input 1 follows the motor's position (drive/axis.h).
TEST(StudioDrive, ASwitchOnTheAxisFollowsThePosition) {
  Studio s("gold");
  s.request({{"op", "switch"}, {"n", 1}, {"from", -10}, {"to", 10}});
  s.run_for(10 * kMs);
  s.drive.broadcast_status();
  EXPECT_EQ(s.recorder.last("status")["inputs"][0], true);  // PX is 0, within [-10, 10]
  s.request({{"op", "switch"}, {"n", 1}, {"from", 100}, {"to", 200}});
  s.run_for(10 * kMs);
  s.drive.broadcast_status();
  EXPECT_EQ(s.recorder.last("status")["inputs"][0], false);
  EXPECT_EQ(s.request({{"op", "switch"}, {"n", 1}, {"from", 5}, {"to", 1}})["type"], "error");
}

TEST(StudioDrive, FaultInjectionLatchesTheMotorFault) {
  Studio s("gold");
  s.request({{"op", "fault"}, {"name", "overcurrent"}});
  EXPECT_EQ(s.recorder.last("status")["motor_fault"].get<uint32_t>() & drive::kFaultOvercurrent,
            drive::kFaultOvercurrent);
  EXPECT_EQ(s.request({{"op", "fault"}, {"name", "gremlins"}})["type"], "error");
}

TEST(StudioDrive, HostileMessagesAreAnsweredAndTheDriveGoesOn) {
  Studio s("gold");
  for (const std::string& bad :
       {std::string("not json"), std::string("[1,2]"), std::string("{\"op\":5}"), std::string("{}"),
        std::string("{\"op\":\"nope\"}"), std::string("{\"op\":\"input\",\"n\":\"x\"}"),
        std::string("{\"op\":\"line\"}"), std::string("{\"op\":\"build\",\"source\":7}"),
        std::string("\xff\xfe{"), std::string("{\"op\":\"scope\",\"channels\":[1e300]}"),
        std::string("{\"op\":\"switch\",\"n\":1,\"from\":1e999}")}) {
    s.recorder.clear();
    s.drive.handle(s.page, bad);
    ASSERT_EQ(s.recorder.messages.size(), 1u) << bad;
    EXPECT_EQ(s.recorder.messages[0]["type"], "error") << bad;
  }
  s.run_for(100 * kMs);
  EXPECT_EQ(s.drive.controller().now_us(), 100'000u);
  EXPECT_EQ(s.line("1+1"), std::vector<std::string>{"2"});
}

// A page gone mid-download takes its download with it (transport::HostSession::disconnect): the
// next page's DL##END has no download to end (210), and the stored program is the one before.
TEST(StudioDrive, APageGoneMidDownloadLeavesTheStoredProgram) {
  const dialect::Dialect& gold = *dialects::find("gold");
  const dialect::SampleProgram& sample = gold.sample_program();
  Studio s("gold", std::string(sample.file_name), std::string(sample.source));
  s.request({{"op", "build"}, {"source", sample.source}});
  ASSERT_EQ(s.recorder.last("build")["ok"], true);
  const auto other = gold.compile_source({"other.ehl", example("gold/first_move.ehl")}, {});
  const auto lines = gold.download_lines(other.stored_form);
  ASSERT_GT(lines.size(), 2u);
  for (size_t i = 0; i + 1 < lines.size(); ++i) {
    EXPECT_TRUE(s.line(lines[i]).empty()) << lines[i];  // DL lines answer nothing but errors
  }
  s.drive.disconnect(s.page);
  PageRecorder second;
  s.page = s.drive.connect(second.sink());
  s.drive.handle(s.page, json({{"op", "line"}, {"text", "DL##END"}}).dump());
  EXPECT_EQ(second.last("answers")["answers"][0]["error"], dialect::kDlNoDownload);
  s.drive.handle(s.page, json({{"op", "start"}}).dump());
  s.run_for(200 * kMs);
  s.drive.handle(s.page, json({{"op", "line"}, {"text", sample.query}}).dump());
  EXPECT_EQ(second.last("answers")["answers"][0]["text"], sample.answer);
}

}  // namespace
}  // namespace uprog::studio
