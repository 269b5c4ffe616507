// The one-line step the line-counting policies share: a program's bare end belongs to its last
// line, a return from a callee does not end the program, and a sleeping thread runs nothing.
#include "dialect/scheduling/line_step.h"

#include <gtest/gtest.h>

#include "scheduling_fixture.h"

namespace uprog::test {
namespace {

using scheduling::step_lines;
using vm::SliceEnd;
using vm::ThreadStatus;

constexpr uint64_t kCap = 1'000'000;

TEST(LineStep, BareEndRunsWithTheLastLine) {
  Drive d;
  ASSERT_TRUE(d.load(counted_writer("t", 7, 3), 1));
  d.start(0, "t");
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::LineEnd);
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::LineEnd);
  const auto last = step_lines(d.machine, 0, 1, kCap);
  EXPECT_EQ(last.end, SliceEnd::Finished);  // the third line's step, not a fourth
  EXPECT_TRUE(last.ran);
  EXPECT_EQ(d.machine.status(0), ThreadStatus::Idle);
  EXPECT_EQ(d.take_trace(), (std::vector<int32_t>{7, 7, 7}));
}

TEST(LineStep, FusedReturnAndExitEndTheLineTheyClose) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.routine task "fused" in=0 out=0 entry=fused
.routine task "exits" in=0 out=0 entry=exits
fused:
  EOL
  RETEOL
exits:
  EOL
  EOL
  EXIT
)",
                     1));
  d.start(0, "fused");
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::LineEnd);
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::Finished);
  d.start(0, "exits");
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::LineEnd);
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::Finished);
}

TEST(LineStep, ReturnFromACalleeIsNotTheEnd) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.routine task "main" in=0 out=0 entry=main
.routine function "sub" in=0 out=0 entry=sub
main:
  CALL sub 0
  PUSHI 2
  CMDSET 1 0
  EOL
  RET
sub:
  PUSHI 1
  CMDSET 1 0
  EOL
  RET
)",
                     1));
  d.start(0, "main");
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::LineEnd);
  EXPECT_EQ(d.take_trace(), std::vector<int32_t>{1});
  EXPECT_EQ(d.machine.frame_count(0), 2u);  // stopped in sub, before its RET
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::Finished);
  EXPECT_EQ(d.take_trace(), std::vector<int32_t>{2});
}

TEST(LineStep, AnEmptyRoutineEndsInOneStep) {
  Drive d;
  ASSERT_TRUE(d.load(".routine task \"e\" in=0 out=0 entry=e\ne:\n  RET\n", 1));
  d.start(0, "e");
  const auto s = step_lines(d.machine, 0, 1, kCap);
  EXPECT_EQ(s.end, SliceEnd::Finished);
  EXPECT_TRUE(s.ran);
}

TEST(LineStep, ASleepingThreadRunsNothingUntilItsTime) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.routine task "t" in=0 out=0 entry=t
t:
  PUSHI 1
  WAIT 1000
  EOL
  PUSHI 5
  CMDSET 1 0
  EOL
  RET
)",
                     1));
  d.start(0, "t");
  const auto first = step_lines(d.machine, 0, 1, kCap);
  EXPECT_EQ(first.end, SliceEnd::Waiting);
  EXPECT_TRUE(first.ran);
  d.host.clock_us = 999;
  const auto asleep = step_lines(d.machine, 0, 1, kCap);
  EXPECT_EQ(asleep.end, SliceEnd::Waiting);
  EXPECT_FALSE(asleep.ran);
  d.host.clock_us = 1000;
  const auto woke = step_lines(d.machine, 0, 1, kCap);
  EXPECT_EQ(woke.end, SliceEnd::LineEnd);  // the rest of the wait's line
  EXPECT_TRUE(woke.ran);
  EXPECT_TRUE(d.take_trace().empty());
  EXPECT_EQ(step_lines(d.machine, 0, 1, kCap).end, SliceEnd::Finished);
  EXPECT_EQ(d.take_trace(), std::vector<int32_t>{5});
}

TEST(LineStep, AWakeThatSleepsAgainAtTheSamePlaceStillRan) {
  // One wait in a loop without other lines: after waking, the step stops at the same WAIT.
  Drive d;
  ASSERT_TRUE(d.load(R"(
.routine task "t" in=0 out=0 entry=t
t:
  PUSHI 1
  WAIT 1000
  JMP.eol t
)",
                     1));
  d.start(0, "t");
  step_lines(d.machine, 0, 2, kCap);
  const uint32_t pc = d.machine.pc(0);
  d.host.clock_us = 1000;
  const auto again = step_lines(d.machine, 0, 2, kCap);
  EXPECT_EQ(again.end, SliceEnd::Waiting);
  EXPECT_EQ(d.machine.pc(0), pc);
  EXPECT_TRUE(again.ran);
}

TEST(LineStep, ALineThatNeverEndsStopsAtTheBackJumpCap) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.global int "n" 1
.routine task "t" in=0 out=0 entry=t
t:
  LDG n
  PUSHI 1
  ADDI
  STG n
  JMP t
)",
                     1));
  d.start(0, "t");
  const auto s = step_lines(d.machine, 0, 1, 250);
  EXPECT_EQ(s.end, SliceEnd::BudgetSpent);
  EXPECT_EQ(d.global("n"), 250);
}

TEST(LineStep, ThreadsThatCannotRunAreLeftAlone) {
  Drive d;
  ASSERT_TRUE(d.load(forever_writer("t", 1), 1));
  EXPECT_FALSE(step_lines(d.machine, 0, 1, kCap).ran);  // idle
  d.start(0, "t");
  d.machine.halt(0);
  const auto s = step_lines(d.machine, 0, 1, kCap);
  EXPECT_FALSE(s.ran);
  EXPECT_EQ(s.end, SliceEnd::NotRunning);
  EXPECT_EQ(d.machine.status(0), ThreadStatus::Halted);
  EXPECT_TRUE(d.take_trace().empty());
}

}  // namespace
}  // namespace uprog::test
