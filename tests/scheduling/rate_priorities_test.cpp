// Round-robin with rate priorities (Akribis, ../shared/spec/akribis-drive.md "Threads and
// events"): each cycle every due thread 1..8 executes one line, in order; priority k makes it
// due every k-th cycle from its start; held threads wait for their release.
#include "dialect/scheduling/rate_priorities.h"

#include <gtest/gtest.h>

#include "scheduling_fixture.h"

namespace uprog::test {
namespace {

using scheduling::kLowestRate;
using scheduling::RatePriorities;
using scheduling::Report;
using scheduling::ThreadEvent;

constexpr uint32_t kCycleUs = 50;

// Threads 0 (the host line's) .. 8; cycle c (from 1) runs at c·50 µs.
struct Cycles {
  Drive d;
  RatePriorities policy;

  bool load(const std::string& text) { return d.load(text, 9); }
  void start(uint32_t thread, const std::string& routine) {
    d.start(thread, routine);
    policy.started(thread);
  }
  Report cycle() {
    d.host.clock_us = static_cast<uint32_t>(policy.cycles() + 1) * kCycleUs;
    return policy.cycle(d.machine);
  }
  // What each of `n` cycles wrote.
  std::vector<std::vector<int32_t>> run(int n) {
    std::vector<std::vector<int32_t>> out;
    for (int i = 0; i < n; ++i) {
      cycle();
      out.push_back(d.take_trace());
    }
    return out;
  }
};

std::string writers(int count) {
  std::string s;
  for (int t = 0; t <= count; ++t) s += forever_writer("t" + std::to_string(t), t);
  return s;
}

// The cycles (1-based, of `trace`) in which `id` was written.
std::vector<int> cycles_of(const std::vector<std::vector<int32_t>>& trace, int32_t id) {
  std::vector<int> out;
  for (size_t c = 0; c < trace.size(); ++c) {
    for (int32_t v : trace[c]) {
      if (v == id) out.push_back(static_cast<int>(c) + 1);
    }
  }
  return out;
}

TEST(RatePriorities, EveryThreadRunsOneLineEachCycleInThreadOrder) {
  Cycles c;
  ASSERT_TRUE(c.load(writers(8)));
  for (uint32_t t = 0; t <= 8; ++t) c.start(t, "t" + std::to_string(t));
  const auto trace = c.run(3);
  const std::vector<int32_t> one_cycle{1, 2, 3, 4, 5, 6, 7, 8};  // thread 0 is not scheduled
  EXPECT_EQ(trace, (std::vector<std::vector<int32_t>>{one_cycle, one_cycle, one_cycle}));
}

TEST(RatePriorities, PriorityKMakesAThreadDueEveryKthCycleFromItsStart) {
  Cycles c;
  ASSERT_TRUE(c.load(writers(3)));
  c.start(1, "t1");
  c.start(2, "t2");
  ASSERT_TRUE(c.policy.set_priority(2, 3));
  auto trace = c.run(5);
  c.start(3, "t3");  // after cycle 5: its cycles count from 6
  ASSERT_TRUE(c.policy.set_priority(3, 4));
  const auto later = c.run(10);
  trace.insert(trace.end(), later.begin(), later.end());
  EXPECT_EQ(cycles_of(trace, 1),
            (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(cycles_of(trace, 2), (std::vector<int>{1, 4, 7, 10, 13}));
  EXPECT_EQ(cycles_of(trace, 3), (std::vector<int>{6, 10, 14}));
}

TEST(RatePriorities, PrioritiesRangeFromOneToAThousand) {
  RatePriorities policy;
  EXPECT_EQ(policy.priority(3), 1u);
  EXPECT_FALSE(policy.set_priority(3, 0));
  EXPECT_FALSE(policy.set_priority(3, kLowestRate + 1));
  EXPECT_EQ(policy.priority(3), 1u);
  EXPECT_TRUE(policy.set_priority(3, 1000));
  EXPECT_EQ(policy.priority(3), 1000u);
  EXPECT_FALSE(policy.set_priority(0, 2));  // the host line's thread is not scheduled
  EXPECT_FALSE(policy.set_priority(9, 2));
  policy.reset();
  EXPECT_EQ(policy.priority(3), 1u);
}

TEST(RatePriorities, TheSlowestRateRunsOnceInAThousandCycles) {
  Cycles c;
  ASSERT_TRUE(c.load(writers(1)));
  c.start(1, "t1");
  ASSERT_TRUE(c.policy.set_priority(1, 1000));
  EXPECT_EQ(cycles_of(c.run(2001), 1), (std::vector<int>{1, 1001, 2001}));
}

TEST(RatePriorities, HeldThreadsWaitForTheirReleaseAndKeepTheirRhythm) {
  Cycles c;
  ASSERT_TRUE(c.load(writers(3)));
  for (uint32_t t = 1; t <= 3; ++t) c.start(t, "t" + std::to_string(t));
  ASSERT_TRUE(c.policy.set_priority(2, 2));  // due 1, 3, 5, 7, ...
  auto trace = c.run(2);
  c.policy.hold(2);
  c.policy.hold(3);
  EXPECT_TRUE(c.policy.held(2));
  auto held = c.run(3);  // cycles 3..5
  c.policy.release(2);
  EXPECT_FALSE(c.policy.held(2));
  EXPECT_TRUE(c.policy.held(3));
  auto released = c.run(3);  // cycles 6..8
  c.policy.release_all();
  auto all = c.run(1);  // cycle 9
  trace.insert(trace.end(), held.begin(), held.end());
  trace.insert(trace.end(), released.begin(), released.end());
  trace.insert(trace.end(), all.begin(), all.end());
  EXPECT_EQ(cycles_of(trace, 1), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(cycles_of(trace, 2), (std::vector<int>{1, 7, 9}));
  EXPECT_EQ(cycles_of(trace, 3), (std::vector<int>{1, 2, 9}));
}

TEST(RatePriorities, AWaitSpendsTheThreadsTurns) {
  Cycles c;
  ASSERT_TRUE(c.load(writers(1) + forever_writer("t3", 3) + routine_header("t2") + write_line(2) +
                     sleep_line(1) + write_forever("t2_loop", 20)));
  for (uint32_t t = 1; t <= 3; ++t) c.start(t, "t" + std::to_string(t));
  // Cycle 2 (100 µs) begins the wait until 1100 µs, cycle 22; that cycle completes the wait's
  // line, and cycle 23 runs the next.
  std::vector<int> ran_2;
  std::vector<std::vector<int32_t>> trace;
  for (int i = 0; i < 24; ++i) {
    if (c.cycle().ran(2)) ran_2.push_back(static_cast<int>(c.policy.cycles()));
    trace.push_back(c.d.take_trace());
  }
  EXPECT_EQ(ran_2, (std::vector<int>{1, 2, 22, 23, 24}));
  EXPECT_EQ(cycles_of(trace, 20), (std::vector<int>{23, 24}));
  EXPECT_EQ(cycles_of(trace, 1).size(), 24u);  // the others run every cycle meanwhile
  EXPECT_EQ(cycles_of(trace, 3).size(), 24u);
}

TEST(RatePriorities, PastItsLastLineAThreadEndsInThatCycle) {
  Cycles c;
  ASSERT_TRUE(c.load(counted_writer("t1", 1, 3)));
  c.start(1, "t1");
  EXPECT_FALSE(c.cycle().has(1, ThreadEvent::Finished));
  EXPECT_FALSE(c.cycle().has(1, ThreadEvent::Finished));
  EXPECT_TRUE(c.cycle().has(1, ThreadEvent::Finished));
  EXPECT_TRUE(c.cycle().empty());
}

TEST(RatePriorities, AThreadStartedByAnotherRunsFromTheNextCycle) {
  Cycles c;
  ASSERT_TRUE(c.load(routine_header("t1") + action_line(2) + write_forever("t1_loop", 1) +
                     forever_writer("t2", 2)));
  c.d.host.on_action = [&c](int32_t thread) {
    c.d.machine.start(static_cast<uint32_t>(thread), c.d.routine("t2"));
    c.policy.started(static_cast<uint32_t>(thread));
  };
  c.start(1, "t1");
  const auto trace = c.run(3);
  EXPECT_EQ(trace, (std::vector<std::vector<int32_t>>{{}, {1, 2}, {1, 2}}));
}

TEST(RatePriorities, ErrorsAndBreakpointsAreReported) {
  Cycles c;
  ASSERT_TRUE(c.load(forever_writer("t1", 1) + routine_header("t2") +
                     "  PUSHI 1\n  PUSHI 0\n  DIVI\n  POP\n  EOL\n  RET\n"));
  c.start(1, "t1");
  c.start(2, "t2");
  ASSERT_TRUE(c.d.machine.set_breakpoint(0));  // thread 1's first line
  const Report r = c.cycle();
  EXPECT_TRUE(r.has(1, ThreadEvent::Breakpoint));
  EXPECT_TRUE(r.has(2, ThreadEvent::Error));
  EXPECT_EQ(r.threads_with_events(), (1u << 1) | (1u << 2));
  EXPECT_TRUE(c.cycle().empty());
}

TEST(RatePriorities, AnIdleDriveHasNothingToDo) {
  Cycles c;
  ASSERT_TRUE(c.load(writers(8)));
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(c.cycle().empty());
  EXPECT_EQ(c.policy.cycles(), 1000u);
}

TEST(RatePriorities, SameInputsSameLinesBitForBit) {
  const auto scenario = [] {
    Cycles c;
    EXPECT_TRUE(c.load(writers(5) + routine_header("t6") + write_line(6) + sleep_line(2) +
                       write_forever("t6_loop", 60)));
    for (uint32_t t = 1; t <= 6; ++t) c.start(t, "t" + std::to_string(t));
    for (uint32_t t = 1; t <= 6; ++t) c.policy.set_priority(t, t);
    auto trace = c.run(100);
    c.policy.hold(3);
    const auto more = c.run(100);
    trace.insert(trace.end(), more.begin(), more.end());
    return trace;
  };
  const auto a = scenario();
  EXPECT_EQ(a, scenario());
  EXPECT_EQ(cycles_of(a, 5).size(), 40u);  // due on cycles 1, 6, ..., 196
}

}  // namespace
}  // namespace uprog::test
