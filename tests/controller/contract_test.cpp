// The dialect contract, proved by a dialect the controller has never heard of (toy_dialect.h):
// the controller runs its cycle on its own period in exact virtual time, keeps its stored form in
// the flash across reboots, gives each host a session of its own, and passes what it prints to
// the output channel.
#include <gtest/gtest.h>

#include <filesystem>

#include "controller/controller.h"
#include "drive/axis.h"
#include "drive/events.h"
#include "support/files.h"
#include "toy_dialect.h"

namespace uprog::controller {
namespace {

ControllerOptions toy_options(std::string state_dir = {}) {
  ControllerOptions o;
  o.dialect = &toy::dialect();
  o.state_dir = std::move(state_dir);
  return o;
}

std::string one(Controller& c, std::string_view line) {
  const auto answers = c.query(line);
  return answers.size() == 1 ? answers[0].text : "<" + std::to_string(answers.size()) + " answers>";
}

std::vector<uint8_t> bytes(std::string_view text) { return {text.begin(), text.end()}; }

TEST(controller_contract, TheFirmwareCyclesOnItsOwnPeriodInExactVirtualTime) {
  Controller c(toy_options());
  c.advance(1000);  // 1 ms: 16 cycles of 62.5 µs, 20 servo cycles of 50 µs
  EXPECT_EQ(one(c, "cycles"), "16");
  EXPECT_EQ(one(c, "ticks"), "1000000");
  c.advance_ns(62'499);  // short of a cycle: nothing happens yet
  EXPECT_EQ(one(c, "cycles"), "16");
  c.advance_ns(1);
  EXPECT_EQ(one(c, "cycles"), "17");
  EXPECT_EQ(c.now_ns(), 1'062'500u);
  c.advance(100'000'000);                   // 100 s more: no drift in 1.6 million cycles
  EXPECT_EQ(c.now_ns(), 100'001'062'500u);  // 100 s + 1.0625 ms
  EXPECT_EQ(one(c, "cycles"), std::to_string(c.now_ns() / 62'500));
}

TEST(controller_contract, TheAxisStepsOnItsServoPeriodAndItsEventsReachTheNextCycle) {
  Controller c(toy_options());
  ASSERT_EQ(c.axis().period_us(), 50u);
  c.advance(10'000);
  EXPECT_EQ(c.axis().cycle_count(), 200u);
  EXPECT_EQ(one(c, "cycles"), "160");
  EXPECT_EQ(one(c, "events"), "0");
  // The input changes between two of the firmware's cycles: the axis reports it at its next
  // servo cycle, and the firmware sees it at its own next cycle.
  c.advance(25);
  c.set_input_level(1, true);
  c.advance(100);
  EXPECT_EQ(std::stoul(one(c, "events")) & drive::general_input_event(1),
            drive::general_input_event(1));
}

TEST(controller_contract, TheStoredFormLivesInTheFlashAcrossReboots) {
  const auto dir = (std::filesystem::temp_directory_path() / "uprog_contract_flash").string();
  std::filesystem::remove_all(dir);
  {
    Controller c(toy_options(dir));
    EXPECT_FALSE(c.download(bytes("nonsense")).ok);  // refused: nothing stored
    EXPECT_FALSE(std::filesystem::exists(dir + "/program.toy"));
    ASSERT_TRUE(c.download(bytes("every 4")).ok);
    EXPECT_EQ(read_binary_file(dir + "/program.toy"), bytes("every 4"));
  }
  Controller again(toy_options(dir));  // power-up: the firmware reads its record
  EXPECT_TRUE(again.boot_messages().empty());
  again.advance(1000);
  EXPECT_EQ(one(again, "count"), "4");  // 16 cycles, every 4th counts
  again.reboot();
  EXPECT_EQ(one(again, "count"), "0");
}

TEST(controller_contract, EachHostHasItsOwnSessionAndTheDriveItsConsole) {
  Controller c(toy_options());
  auto a = c.open_session(), b = c.open_session();
  EXPECT_EQ(c.send("hello").front().text, "session 1");  // the console opened first
  EXPECT_EQ(a->send("hello").front().text, "session 2");
  EXPECT_EQ(b->send("hello").front().text, "session 3");
}

TEST(controller_contract, WhatTheProgramPrintsReachesTheOutputChannelInOrder) {
  Controller c(toy_options());
  EXPECT_TRUE(c.send("say one").empty());
  EXPECT_TRUE(c.send("say two").empty());
  EXPECT_EQ(c.take_output(), (std::vector<std::string>{"one\n", "two\n"}));
  EXPECT_TRUE(c.take_output().empty());
}

TEST(controller_contract, TheControllerStartsAndDescribesAProgramThroughTheFirmware) {
  Controller c(toy_options());
  EXPECT_EQ(c.start_program(), "no program");
  ASSERT_TRUE(c.download(bytes("every 2")).ok);
  EXPECT_EQ(c.start_program(), "");
  EXPECT_TRUE(c.program_running());
  c.advance(1000);
  EXPECT_EQ(c.firmware().state_summary(), "count=8");
}

}  // namespace
}  // namespace uprog::controller
