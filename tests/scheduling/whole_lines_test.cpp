// Whole lines per background slice (Gold, manual 2.2 and docs/controller.md "Time"): N lines a
// slice, or unlimited until a wait, a yield or the end, capped by lines and by jumps back.
#include "dialect/scheduling/whole_lines.h"

#include <gtest/gtest.h>

#include "scheduling_fixture.h"

namespace uprog::test {
namespace {

using scheduling::LineTiming;
using scheduling::ThreadEvent;
using scheduling::WholeLines;
using vm::ThreadStatus;

TEST(WholeLines, OneLinePerSliceByDefault) {
  Drive d;
  ASSERT_TRUE(d.load(counted_writer("main", 4, 3), 1));
  d.start(0, "main");
  const WholeLines policy;
  for (int slice = 0; slice < 3; ++slice) {
    const auto r = policy.slice(d.machine, 0);
    EXPECT_EQ(d.take_trace(), std::vector<int32_t>{4}) << slice;
    EXPECT_TRUE(r.ran(0));
    EXPECT_EQ(r.threads_with_events(), 0u);
  }
  // As the controller does today: the RET after the last line's end takes a slice of its own.
  const auto end = policy.slice(d.machine, 0);
  EXPECT_TRUE(end.has(0, ThreadEvent::Finished));
  EXPECT_TRUE(d.take_trace().empty());
  EXPECT_TRUE(policy.slice(d.machine, 0).empty());  // idle now: nothing to do
}

TEST(WholeLines, NLinesPerSlice) {
  Drive d;
  ASSERT_TRUE(d.load(forever_writer("main", 2), 1));
  d.start(0, "main");
  const WholeLines policy(LineTiming{3});
  policy.slice(d.machine, 0);
  EXPECT_EQ(d.take_trace(), (std::vector<int32_t>{2, 2, 2}));
  policy.slice(d.machine, 0);
  EXPECT_EQ(d.take_trace().size(), 3u);
}

TEST(WholeLines, BudgetIsTheControllersTiming) {
  EXPECT_EQ(WholeLines().budget().lines, 1u);
  EXPECT_EQ(WholeLines().budget().instructions, 0u);
  EXPECT_EQ(WholeLines().budget().back_jumps, 1'000'000u);
  LineTiming unlimited;
  unlimited.unlimited = true;
  unlimited.lines_per_cycle = 5;  // ignored when unlimited
  EXPECT_EQ(WholeLines(unlimited).budget().lines, 1'000'000u);
}

TEST(WholeLines, UnlimitedRunsUntilAWait) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  CMDSET 1 0
  EOL
  PUSHI 2
  CMDSET 1 0
  EOL
  PUSHI 1
  WAIT 1000
  EOL
  PUSHI 3
  CMDSET 1 0
  EOL
  RET
)",
                     1));
  d.start(0, "main");
  LineTiming t;
  t.unlimited = true;
  const WholeLines policy(t);
  EXPECT_TRUE(policy.slice(d.machine, 0).ran(0));
  EXPECT_EQ(d.take_trace(), (std::vector<int32_t>{1, 2}));
  EXPECT_EQ(d.machine.status(0), ThreadStatus::Waiting);
  d.host.clock_us = 999;
  const auto asleep = policy.slice(d.machine, 0);
  EXPECT_FALSE(asleep.ran(0));
  EXPECT_TRUE(asleep.empty());
  d.host.clock_us = 1000;
  const auto woke = policy.slice(d.machine, 0);
  EXPECT_TRUE(woke.ran(0));
  EXPECT_TRUE(woke.has(0, ThreadEvent::Finished));
  EXPECT_EQ(d.take_trace(), std::vector<int32_t>{3});
}

TEST(WholeLines, UnlimitedStopsAtTheLineCap) {
  Drive d;
  ASSERT_TRUE(d.load(forever_writer("main", 9), 1));
  d.start(0, "main");
  LineTiming t;
  t.unlimited = true;
  t.unlimited_line_cap = 7;
  const WholeLines policy(t);
  policy.slice(d.machine, 0);
  EXPECT_EQ(d.take_trace().size(), 7u);
  policy.slice(d.machine, 0);
  EXPECT_EQ(d.take_trace().size(), 7u);  // it continues in the next slice
}

TEST(WholeLines, ALoopWithoutLineEndsStopsAtTheBackJumpCap) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.global int "n" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG n
  PUSHI 1
  ADDI
  STG n
  JMP main
)",
                     1));
  d.start(0, "main");
  LineTiming t;
  t.unlimited = true;
  t.back_jump_cap = 1000;
  const WholeLines policy(t);
  policy.slice(d.machine, 0);
  EXPECT_EQ(d.global("n"), 1000);
  policy.slice(d.machine, 0);
  EXPECT_EQ(d.global("n"), 2000);
}

TEST(WholeLines, ReportsErrorsAndBreakpoints) {
  Drive d;
  ASSERT_TRUE(d.load(R"(
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  CMDSET 1 0
  EOL
  PUSHI 1
  PUSHI 0
  DIVI
  POP
  EOL
  RET
)",
                     1));
  d.start(0, "main");
  ASSERT_TRUE(d.machine.set_breakpoint(4));  // the second line's first instruction
  const WholeLines policy(LineTiming{10});
  const auto at_break = policy.slice(d.machine, 0);
  EXPECT_TRUE(at_break.has(0, ThreadEvent::Breakpoint));
  EXPECT_FALSE(at_break.has(0, ThreadEvent::Error));
  EXPECT_TRUE(policy.slice(d.machine, 0).empty());  // at a breakpoint: left alone
  d.machine.resume(0);
  const auto failed = policy.slice(d.machine, 0);
  EXPECT_TRUE(failed.has(0, ThreadEvent::Error));
  EXPECT_EQ(d.machine.last_error(0), vm::RunError::DivisionByZero);
  EXPECT_TRUE(policy.slice(d.machine, 0).empty());  // stopped by the error
}

TEST(WholeLines, HaltedThreadIsLeftAlone) {
  Drive d;
  ASSERT_TRUE(d.load(forever_writer("main", 1), 1));
  d.start(0, "main");
  const WholeLines policy;
  policy.slice(d.machine, 0);
  d.machine.halt(0);
  const uint32_t pc = d.machine.pc(0);
  EXPECT_TRUE(policy.slice(d.machine, 0).empty());
  EXPECT_EQ(d.machine.pc(0), pc);
  EXPECT_EQ(d.take_trace().size(), 1u);
}

}  // namespace
}  // namespace uprog::test
