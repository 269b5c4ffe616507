// Cyclic tasks (S300, ../shared/spec/s300-drive.md "Tasks, time and load"): 62.5 µs ticks, due
// tasks run to completion fastest first within period/0.16 µs lines, one line more is an
// overrun; the init task alone first; the background loop on the lines left; TASK's figures.
#include "dialect/scheduling/cyclic_tasks.h"

#include <gtest/gtest.h>

#include "scheduling_fixture.h"

namespace uprog::test {
namespace {

using scheduling::CyclicTasks;
using scheduling::Report;
using scheduling::ThreadEvent;
using vm::ThreadStatus;

constexpr uint64_t kTickNs = 62'500;
constexpr uint64_t kStepNs = 125'000;  // the axis step: the firmware calls run() after each
constexpr uint64_t kMs = 1'000'000;

// A task of `lines` empty lines, ending with a bare RET.
std::string plain_lines(const std::string& name, int lines) {
  std::string s = routine_header(name);
  for (int i = 0; i < lines; ++i) s += "  EOL\n";
  return s + "  RET\n";
}

struct Ticks {
  Drive d;
  CyclicTasks policy;

  bool load(const std::string& text) {
    if (!d.load(text, 8)) return false;
    d.host.on_action = [this](int32_t lines) { policy.charge(static_cast<uint64_t>(lines)); };
    return true;
  }
  uint32_t routine(const std::string& name) const { return d.routine(name); }
  Report run_at(uint64_t now_ns) {
    d.host.clock_us = static_cast<uint32_t>(now_ns / 1000);
    return policy.run(d.machine, now_ns);
  }
};

TEST(CyclicTasks, BudgetsArePeriodOverLineTime) {
  CyclicTasks policy;
  // Added slowest first: they run fastest first.
  ASSERT_TRUE(policy.add_task(5, 0, 16 * kMs));
  ASSERT_TRUE(policy.add_task(4, 0, 4 * kMs));
  ASSERT_TRUE(policy.add_task(3, 0, 1 * kMs));
  ASSERT_TRUE(policy.add_task(2, 0, 250'000));
  ASSERT_TRUE(policy.add_task(1, 0, 62'500));
  ASSERT_EQ(policy.task_count(), 5u);
  const uint64_t budgets[] = {390, 1562, 6250, 25'000, 100'000};
  for (uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(policy.stats(i).thread, i + 1);
    EXPECT_EQ(policy.stats(i).budget_lines, budgets[i]);
  }
  EXPECT_EQ(policy.stats(5).thread, scheduling::kNoThread);  // no such task
  EXPECT_EQ(policy.stats(5).budget_lines, 0u);
}

TEST(CyclicTasks, PeriodsAreWholeTicks) {
  CyclicTasks policy;
  EXPECT_FALSE(policy.add_task(1, 0, 0));
  EXPECT_FALSE(policy.add_task(1, 0, 100'000));
  EXPECT_FALSE(policy.add_task(1, 0, kTickNs + 1));
  for (uint32_t i = 0; i < CyclicTasks::kMaxTasks; ++i) EXPECT_TRUE(policy.add_task(i, 0, kTickNs));
  EXPECT_FALSE(policy.add_task(9, 0, kTickNs));
}

TEST(CyclicTasks, DueTasksRunEachTickFastestFirst) {
  Ticks t;
  ASSERT_TRUE(t.load(counted_writer("plc62", 62, 1) + counted_writer("plc250", 250, 1) +
                     counted_writer("plc1", 1000, 1) + counted_writer("plc4", 4000, 1) +
                     counted_writer("plc16", 16000, 1)));
  ASSERT_TRUE(t.policy.add_task(5, t.routine("plc16"), 16 * kMs));
  ASSERT_TRUE(t.policy.add_task(3, t.routine("plc1"), kMs));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.add_task(4, t.routine("plc4"), 4 * kMs));
  ASSERT_TRUE(t.policy.add_task(2, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  std::vector<std::vector<int32_t>> ticks;
  for (uint64_t k = 1; k <= 256; ++k) {
    t.run_at(k * kTickNs);
    ticks.push_back(t.d.take_trace());
  }
  EXPECT_EQ(ticks[0], (std::vector<int32_t>{62, 250, 1000, 4000, 16000}));
  EXPECT_EQ(ticks[1], (std::vector<int32_t>{62}));
  EXPECT_EQ(ticks[4], (std::vector<int32_t>{62, 250}));
  EXPECT_EQ(ticks[16], (std::vector<int32_t>{62, 250, 1000}));
  EXPECT_EQ(ticks[64], (std::vector<int32_t>{62, 250, 1000, 4000}));
  std::map<int32_t, int> runs;
  for (const auto& tick : ticks) {
    for (int32_t id : tick) ++runs[id];
  }
  EXPECT_EQ(runs,
            (std::map<int32_t, int>{{62, 256}, {250, 64}, {1000, 16}, {4000, 4}, {16000, 1}}));
  for (uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(t.policy.stats(i).runs, static_cast<uint64_t>(256 >> (2 * i)));
    EXPECT_EQ(t.policy.stats(i).last_run_lines, 1u);
  }
}

TEST(CyclicTasks, ARunMayUseItsWholeBudget) {
  // 390 lines and a bare RET, or 389 lines and one that ends and returns (RETEOL): 390 each.
  std::string fused = routine_header("plc62");
  for (int i = 0; i < 389; ++i) fused += "  EOL\n";
  fused += "  RETEOL\n";
  for (const std::string& text : {plain_lines("plc62", 390), fused}) {
    Ticks t;
    ASSERT_TRUE(t.load(text));
    ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
    ASSERT_TRUE(t.policy.start(t.d.machine, 0));
    for (uint64_t k = 1; k <= 10; ++k) {
      const Report r = t.run_at(k * kTickNs);
      ASSERT_EQ(r.threads_with_events(), 0u) << k;
      ASSERT_TRUE(r.ran(1));
    }
    EXPECT_EQ(t.policy.stats(0).runs, 10u);
    EXPECT_EQ(t.policy.stats(0).largest_run_lines, 390u);
    EXPECT_EQ(t.policy.stats(0).largest_run_percent(), 100u);
    EXPECT_EQ(t.policy.stats(0).overruns, 0u);
  }
}

TEST(CyclicTasks, OneLineMoreIsAnOverrun) {
  Ticks t;
  ASSERT_TRUE(t.load(plain_lines("plc62", 391)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  const Report r = t.run_at(kTickNs);
  EXPECT_TRUE(r.has(1, ThreadEvent::Overrun));
  EXPECT_EQ(t.d.machine.status(1), ThreadStatus::Halted);  // before its 391st line
  EXPECT_EQ(t.d.machine.pc(1), 390u);
  EXPECT_EQ(t.policy.stats(0).overruns, 1u);
  EXPECT_EQ(t.policy.stats(0).runs, 0u);
  EXPECT_EQ(t.policy.stats(0).largest_run_lines, 390u);
  // Stopped until start(): later ticks leave it alone.
  const Report later = t.run_at(2 * kTickNs);
  EXPECT_TRUE(later.empty());
}

TEST(CyclicTasks, AnOverrunEndsTheCall) {
  Ticks t;
  ASSERT_TRUE(t.load(plain_lines("plc62", 400) + counted_writer("plc250", 250, 1) +
                     forever_writer("main", 5)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.add_task(2, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.set_background(3, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  const Report r = t.run_at(kStepNs);
  EXPECT_TRUE(r.has(1, ThreadEvent::Overrun));
  EXPECT_FALSE(r.ran(2));  // after the overrun in its tick: not run
  EXPECT_FALSE(r.ran(3));  // nor the background
  EXPECT_TRUE(t.d.take_trace().empty());
}

TEST(CyclicTasks, AChargeCountsAsLinesAndCanOverrun) {
  Ticks t;
  ASSERT_TRUE(t.load(routine_header("plc1") + write_line(1) + write_line(2) + action_line(625) +
                     "  EOL\n  EOL\n  EOL\n  EOL\n  EOL\n  EOL\n  EOL\n  RET\n"));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc1"), kMs));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  for (uint64_t k = 1; k <= 16; ++k) t.run_at(k * kTickNs);
  EXPECT_EQ(t.policy.stats(0).runs, 1u);
  EXPECT_EQ(t.policy.stats(0).largest_run_lines, 635u);  // 10 lines and one host call of 625
  EXPECT_EQ(t.policy.stats(0).largest_run_percent(), 10u);

  // The same call in a task of 390 lines: its one line and run end, but over the budget.
  Ticks fast;
  ASSERT_TRUE(fast.load(routine_header("plc62") + action_line(625) + "  RET\n"));
  ASSERT_TRUE(fast.policy.add_task(1, fast.routine("plc62"), kTickNs));
  ASSERT_TRUE(fast.policy.start(fast.d.machine, 0));
  EXPECT_TRUE(fast.run_at(kTickNs).has(1, ThreadEvent::Overrun));
  EXPECT_EQ(fast.policy.stats(0).largest_run_lines, 626u);
  EXPECT_EQ(fast.policy.stats(0).largest_run_percent(), 160u);
}

TEST(CyclicTasks, ARunTimeErrorEndsTheCallAndStopsTheTask) {
  Ticks t;
  ASSERT_TRUE(t.load(routine_header("plc62") +
                     "  PUSHI 1\n  PUSHI 0\n  DIVI\n  POP\n  EOL\n  RET\n" +
                     counted_writer("plc250", 250, 1)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.add_task(2, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  const Report r = t.run_at(kTickNs);
  EXPECT_TRUE(r.has(1, ThreadEvent::Error));
  EXPECT_EQ(t.d.machine.last_error(1), vm::RunError::DivisionByZero);
  EXPECT_FALSE(r.ran(2));
  const Report next = t.run_at(5 * kTickNs);  // ticks 2..5: plc250 runs at 5, plc62 no more
  EXPECT_FALSE(next.ran(1));
  EXPECT_TRUE(next.ran(2));
  EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{250});
}

TEST(CyclicTasks, LargestRunIsInPercentOfTheBudget) {
  std::string text = routine_header("plc250") + "  CMDGET 1 0\n  JNZ long\n";
  for (int i = 0; i < 100; ++i) text += "  EOL\n";
  text += "  RET\nlong:\n";
  for (int i = 0; i < 781; ++i) text += "  EOL\n";
  text += "  RET\n";
  Ticks t;
  ASSERT_TRUE(t.load(text));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  t.run_at(kTickNs);  // runs at ticks 1, 5, 9
  EXPECT_EQ(t.policy.stats(0).largest_run_lines, 100u);
  EXPECT_EQ(t.policy.stats(0).largest_run_percent(), 6u);  // 100 of 1562
  t.d.host.registers[0] = Value::of_int(1);
  t.run_at(5 * kTickNs);
  EXPECT_EQ(t.policy.stats(0).largest_run_percent(), 50u);  // 781 of 1562
  t.d.host.registers[0] = Value::of_int(0);
  t.run_at(9 * kTickNs);
  EXPECT_EQ(t.policy.stats(0).runs, 3u);
  EXPECT_EQ(t.policy.stats(0).last_run_lines, 100u);
  EXPECT_EQ(t.policy.stats(0).largest_run_lines, 781u);
}

TEST(CyclicTasks, ATenLineBackgroundAloneLoops625000TimesASecond) {
  Ticks t;
  ASSERT_TRUE(t.load(plain_lines("main", 10)));
  ASSERT_TRUE(t.policy.set_background(1, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  for (uint64_t k = 1; k < 8000; ++k) t.run_at(k * kStepNs);
  EXPECT_EQ(t.policy.background_loops_last_second(), 0u);  // no whole second yet
  t.run_at(8000 * kStepNs);
  EXPECT_EQ(t.policy.background_loops_last_second(), 625'000u);  // 6250 lines a ms, 10 a loop
  for (uint64_t k = 8001; k <= 16000; ++k) t.run_at(k * kStepNs);
  EXPECT_EQ(t.policy.background_loops_last_second(), 625'000u);
}

TEST(CyclicTasks, TheBackgroundGetsWhatTheRealTimeTasksLeave) {
  Ticks t;
  ASSERT_TRUE(t.load(plain_lines("plc62", 100) + plain_lines("main", 10)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.set_background(2, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  for (uint64_t k = 1; k <= 8000; ++k) t.run_at(k * kStepNs);
  // 6 250 000 lines a second, of which 16 000 runs of 100 lines: 4 650 000 for 10-line loops.
  EXPECT_EQ(t.policy.stats(0).runs, 16'000u);
  EXPECT_EQ(t.policy.background_loops_last_second(), 465'000u);
}

TEST(CyclicTasks, ADebtOfTheRealTimeTasksCarriesOver) {
  // 390 lines each tick and a 1562-line run every 4th: 3122 lines in 4 ticks, of 1562.5 the
  // CPU has. The background gets nothing while the debt lasts.
  Ticks t;
  ASSERT_TRUE(
      t.load(plain_lines("plc62", 390) + plain_lines("plc250", 1562) + forever_writer("main", 5)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.add_task(2, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.set_background(3, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  for (uint64_t k = 1; k <= 800; ++k) ASSERT_FALSE(t.run_at(k * kStepNs).ran(3)) << k;
  EXPECT_TRUE(t.d.take_trace().empty());
}

TEST(CyclicTasks, TheInitTaskRunsAloneFirst) {
  std::string init = routine_header("init") + write_line(7);
  for (int i = 0; i < 1998; ++i) init += "  EOL\n";
  init += write_line(8) + "  RET\n";
  Ticks t;
  ASSERT_TRUE(t.load(init + counted_writer("plc62", 62, 1) + forever_writer("main", 5)));
  ASSERT_TRUE(t.policy.set_init(1, t.routine("init")));
  ASSERT_TRUE(t.policy.add_task(2, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.set_background(3, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  // 125 µs give 781.25 lines: the 2000 lines of init take three steps, alone.
  EXPECT_FALSE(t.run_at(kStepNs).has(1, ThreadEvent::Finished));
  EXPECT_FALSE(t.run_at(2 * kStepNs).has(1, ThreadEvent::Finished));
  EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{7});
  const Report done = t.run_at(3 * kStepNs);
  EXPECT_TRUE(done.has(1, ThreadEvent::Finished));
  EXPECT_FALSE(done.ran(2));
  EXPECT_FALSE(done.ran(3));
  EXPECT_TRUE(t.policy.init_done());
  EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{8});
  // Then the real-time task from the next tick, and the background on the rest: 782 lines
  // (the remainders of four steps make one more) less the two of plc62.
  t.run_at(4 * kStepNs);
  std::vector<int32_t> expected{62, 62};
  expected.insert(expected.end(), 780, 5);
  EXPECT_EQ(t.d.take_trace(), expected);
}

TEST(CyclicTasks, AWaitPausesTheRunUntilTheTaskIsNextDue) {
  Ticks t;
  ASSERT_TRUE(t.load(routine_header("plc250") + write_line(1) + "  YIELD\n  EOL\n" + write_line(2) +
                     "  RET\n"));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  t.run_at(4 * kTickNs);
  EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{1});
  EXPECT_EQ(t.policy.stats(0).runs, 0u);
  t.run_at(5 * kTickNs);
  EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{2});
  EXPECT_EQ(t.policy.stats(0).runs, 1u);
  EXPECT_EQ(t.policy.stats(0).last_run_lines, 3u);
}

TEST(CyclicTasks, ABreakpointSuspendsTheRunUntilResumed) {
  Ticks t;
  ASSERT_TRUE(t.load(counted_writer("plc62", 62, 3)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  ASSERT_TRUE(t.d.machine.set_breakpoint(4));  // the second line
  EXPECT_TRUE(t.run_at(kTickNs).has(1, ThreadEvent::Breakpoint));
  EXPECT_TRUE(t.run_at(2 * kTickNs).empty());
  t.d.machine.resume(1);
  t.run_at(3 * kTickNs);
  EXPECT_EQ(t.d.take_trace(), (std::vector<int32_t>{62, 62, 62}));
  EXPECT_EQ(t.policy.stats(0).runs, 1u);
  EXPECT_EQ(t.policy.stats(0).last_run_lines, 3u);
}

// The debug commands' hold (PLCHOLD, PLCSTEP, PLCCONT): a task held between runs begins none,
// a step runs one line of a new run, and the run it ends counts; released, it runs when next due.
TEST(CyclicTasks, AHeldTaskBeginsNoRunAndStepsLineByLine) {
  Ticks t;
  ASSERT_TRUE(t.load(counted_writer("plc62", 62, 3)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  t.policy.hold(t.d.machine, 1);
  for (uint64_t k = 1; k <= 4; ++k) EXPECT_TRUE(t.run_at(k * kTickNs).empty()) << k;
  EXPECT_TRUE(t.d.take_trace().empty());
  EXPECT_TRUE(t.policy.held(t.d.machine, 1));
  Report report;
  for (uint64_t line = 1; line <= 3; ++line) {
    ASSERT_TRUE(t.policy.step_held(t.d.machine, 1, report)) << line;
    EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{62}) << line;
    EXPECT_EQ(t.policy.stats(0).runs, line == 3 ? 1u : 0u) << line;
    EXPECT_TRUE(t.policy.held(t.d.machine, 1)) << line;
  }
  EXPECT_EQ(t.d.machine.status(1), ThreadStatus::Idle);  // between runs, still held
  EXPECT_TRUE(t.run_at(5 * kTickNs).empty());
  EXPECT_EQ(t.policy.stats(0).overruns, 0u);
  t.policy.release(t.d.machine, 1);
  EXPECT_FALSE(t.policy.held(t.d.machine, 1));
  t.run_at(6 * kTickNs);
  EXPECT_EQ(t.d.take_trace(), (std::vector<int32_t>{62, 62, 62}));
  EXPECT_EQ(t.policy.stats(0).runs, 2u);
}

// A run held in its middle goes on as the same run once released; a task not held cannot step.
TEST(CyclicTasks, AReleasedRunGoesOnAtItsNextDueTick) {
  Ticks t;
  ASSERT_TRUE(t.load(counted_writer("plc250", 250, 3)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc250"), 250'000));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  t.run_at(kTickNs);  // run 1, on tick 1
  EXPECT_EQ(t.d.take_trace(), (std::vector<int32_t>{250, 250, 250}));
  Report report;
  EXPECT_FALSE(t.policy.step_held(t.d.machine, 1, report));
  t.policy.hold(t.d.machine, 1);
  ASSERT_TRUE(t.policy.step_held(t.d.machine, 1, report));  // run 2 begins
  EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{250});
  EXPECT_EQ(t.d.machine.status(1), ThreadStatus::Halted);
  t.policy.release(t.d.machine, 1);
  t.run_at(4 * kTickNs);  // not due until tick 5
  EXPECT_TRUE(t.d.take_trace().empty());
  t.run_at(5 * kTickNs);
  EXPECT_EQ(t.d.take_trace(), (std::vector<int32_t>{250, 250}));
  EXPECT_EQ(t.policy.stats(0).runs, 2u);
  EXPECT_EQ(t.policy.stats(0).last_run_lines, 2u);  // the stepped line costs no budget
}

// Stepping the init task to its end starts the others; a real-time task cannot step before.
TEST(CyclicTasks, AStepThatEndsTheInitTaskStartsTheOthers) {
  Ticks t;
  ASSERT_TRUE(t.load(counted_writer("init", 7, 2) + counted_writer("plc62", 62, 1) +
                     counted_writer("main", 5, 1)));
  ASSERT_TRUE(t.policy.set_init(1, t.routine("init")));
  ASSERT_TRUE(t.policy.add_task(2, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.set_background(3, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  t.policy.hold(t.d.machine, 1);
  t.policy.hold(t.d.machine, 2);
  EXPECT_TRUE(t.run_at(kStepNs).empty());
  Report report;
  EXPECT_FALSE(t.policy.step_held(t.d.machine, 2, report));
  ASSERT_TRUE(t.policy.step_held(t.d.machine, 1, report));
  EXPECT_FALSE(t.policy.init_done());
  ASSERT_TRUE(t.policy.step_held(t.d.machine, 1, report));
  EXPECT_TRUE(report.has(1, ThreadEvent::Finished));
  EXPECT_TRUE(t.policy.init_done());
  EXPECT_EQ(t.d.take_trace(), (std::vector<int32_t>{7, 7}));
  EXPECT_FALSE(t.policy.step_held(t.d.machine, 1, report));  // nothing left to run
  // The background runs; the held real-time task does not.
  t.run_at(2 * kStepNs);
  const std::vector<int32_t> trace = t.d.take_trace();
  EXPECT_FALSE(trace.empty());
  for (int32_t v : trace) EXPECT_EQ(v, 5);
}

// The background's last line, stepped, goes on to its top, held there.
TEST(CyclicTasks, AStepAtTheBackgroundsEndGoesToItsTop) {
  Ticks t;
  ASSERT_TRUE(t.load(counted_writer("main", 5, 1)));
  ASSERT_TRUE(t.policy.set_background(1, t.routine("main")));
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  t.policy.hold(t.d.machine, 1);
  EXPECT_TRUE(t.run_at(kStepNs).empty());
  Report report;
  for (int pass = 0; pass < 2; ++pass) {
    ASSERT_TRUE(t.policy.step_held(t.d.machine, 1, report));
    EXPECT_EQ(t.d.take_trace(), std::vector<int32_t>{5});
    EXPECT_EQ(t.d.machine.status(1), ThreadStatus::Halted);
    EXPECT_EQ(t.d.machine.pc(1), t.d.machine.image().routines[t.routine("main")].entry);
  }
}

TEST(CyclicTasks, StopEndsEverything) {
  Ticks t;
  ASSERT_TRUE(t.load(forever_writer("plc62", 62) + plain_lines("main", 10)));
  ASSERT_TRUE(t.policy.add_task(1, t.routine("plc62"), kTickNs));
  ASSERT_TRUE(t.policy.set_background(2, t.routine("main")));
  EXPECT_TRUE(t.run_at(kStepNs).empty());  // not started: nothing to do
  ASSERT_TRUE(t.policy.start(t.d.machine, 0));
  for (uint64_t k = 1; k <= 8000; ++k) t.run_at(k * kStepNs);
  EXPECT_GT(t.policy.background_loops_last_second(), 0u);
  t.policy.stop(t.d.machine);
  EXPECT_FALSE(t.policy.started());
  EXPECT_EQ(t.d.machine.status(1), ThreadStatus::Idle);
  EXPECT_EQ(t.d.machine.status(2), ThreadStatus::Idle);
  EXPECT_EQ(t.policy.background_loops_last_second(), 0u);
  EXPECT_TRUE(t.run_at(8001 * kStepNs).empty());
}

TEST(CyclicTasks, StartRefusesWhatCannotRun) {
  Ticks t;
  ASSERT_TRUE(t.load(plain_lines("a", 1) + plain_lines("b", 1) +
                     ".routine function \"f\" in=1 out=0 entry=f\n.local int \"x\"\nf:\n  RET\n"));
  {
    CyclicTasks twice;
    twice.add_task(1, t.routine("a"), kTickNs);
    twice.add_task(1, t.routine("b"), kTickNs);
    EXPECT_FALSE(twice.start(t.d.machine, 0));
  }
  {
    CyclicTasks shared;
    shared.add_task(1, t.routine("a"), kTickNs);
    shared.set_background(1, t.routine("b"));
    EXPECT_FALSE(shared.start(t.d.machine, 0));
  }
  {
    CyclicTasks beyond;
    beyond.add_task(8, t.routine("a"), kTickNs);  // the machine has threads 0..7
    EXPECT_FALSE(beyond.start(t.d.machine, 0));
  }
  {
    CyclicTasks inputs;
    inputs.add_task(1, t.routine("f"), kTickNs);
    EXPECT_FALSE(inputs.start(t.d.machine, 0));
    EXPECT_EQ(t.d.machine.status(1), ThreadStatus::Idle);
  }
  {
    CyclicTasks init_and_main;  // one thread for both: init ends before the background starts
    init_and_main.set_init(1, t.routine("a"));
    init_and_main.set_background(1, t.routine("b"));
    EXPECT_TRUE(init_and_main.start(t.d.machine, 0));
    EXPECT_FALSE(init_and_main.add_task(2, t.routine("a"), kTickNs));  // not while started
  }
}

TEST(CyclicTasks, SameInputsSameRunsBitForBit) {
  const auto scenario = [] {
    Ticks t;
    EXPECT_TRUE(t.load(routine_header("plc62") + write_line(62) + action_line(40) + "  RET\n" +
                       plain_lines("plc1", 3000) + routine_header("main") + write_line(5) +
                       action_line(625) + write_line(6) + "  RET\n" + plain_lines("init", 900)));
    t.policy.add_task(1, t.routine("plc62"), kTickNs);
    t.policy.add_task(2, t.routine("plc1"), kMs);
    t.policy.set_init(3, t.routine("init"));
    t.policy.set_background(4, t.routine("main"));
    t.policy.start(t.d.machine, 0);
    std::vector<uint64_t> figures;
    for (uint64_t k = 1; k <= 20000; ++k) t.run_at(k * kStepNs);
    for (uint32_t i = 0; i < 2; ++i) {
      figures.push_back(t.policy.stats(i).runs);
      figures.push_back(t.policy.stats(i).largest_run_lines);
    }
    figures.push_back(t.policy.background_loops_last_second());
    return std::pair{figures, t.d.take_trace()};
  };
  const auto a = scenario();
  EXPECT_EQ(a, scenario());
  EXPECT_EQ(a.first[1], 42u);  // plc62: 2 lines and a charge of 40
  EXPECT_GT(a.first[4], 0u);
}

}  // namespace
}  // namespace uprog::test
