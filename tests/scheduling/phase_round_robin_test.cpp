// Round-robin, one command per phase (PDL, ../shared/spec/pdl-drive.md "Phases and tasks"):
// turns 1, 2, 3, 1, ... over the active tasks, task 0 none; a condition wait spends its turn, a
// sleep is out of turn; a lock gives its holder every phase until it unlocks or ends.
#include "dialect/scheduling/phase_round_robin.h"

#include <gtest/gtest.h>

#include "scheduling_fixture.h"

namespace uprog::test {
namespace {

using scheduling::kNoThread;
using scheduling::PhaseResult;
using scheduling::PhaseRoundRobin;
using scheduling::ThreadEvent;

constexpr uint32_t kNone = kNoThread;
constexpr uint32_t kPhaseUs = 50;
constexpr int kLock = 1;
constexpr int kUnlock = 2;

// A drive with the system's task 0 and tasks 1..3; phase p runs at p·50 µs.
struct Phases {
  Drive d;
  PhaseRoundRobin policy;
  uint32_t next_phase = 0;
  std::vector<uint32_t> turns;

  bool load(const std::string& text) {
    if (!d.load(text, 4)) return false;
    d.host.on_action = [this](int32_t code) {
      if (code == kLock) policy.lock(policy.running());
      if (code == kUnlock) policy.unlock(policy.running());
    };
    return true;
  }
  PhaseResult phase() {
    d.host.clock_us = next_phase++ * kPhaseUs;
    PhaseResult r = policy.phase(d.machine);
    turns.push_back(r.turn);
    return r;
  }
  void run(int n) {
    for (int i = 0; i < n; ++i) phase();
  }
};

std::vector<uint32_t> repeat(std::vector<uint32_t> pattern, int times) {
  std::vector<uint32_t> out;
  for (int i = 0; i < times; ++i) out.insert(out.end(), pattern.begin(), pattern.end());
  return out;
}
std::vector<uint32_t> concat(std::initializer_list<std::vector<uint32_t>> parts) {
  std::vector<uint32_t> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

TEST(PhaseRoundRobin, TurnsGoInTaskOrderOneCommandEachAndTaskZeroGetsNone) {
  Phases p;
  ASSERT_TRUE(p.load(forever_writer("t0", 0) + forever_writer("t1", 1) + forever_writer("t2", 2) +
                     forever_writer("t3", 3)));
  for (uint32_t t = 0; t < 4; ++t) p.d.start(t, "t" + std::to_string(t));
  p.run(9);
  EXPECT_EQ(p.turns, repeat({1, 2, 3}, 3));
  EXPECT_EQ(p.d.take_trace(), (std::vector<int32_t>{1, 2, 3, 1, 2, 3, 1, 2, 3}));
}

TEST(PhaseRoundRobin, IdleTasksHaveNoTurnAndAStartedOneJoinsInOrder) {
  Phases p;
  ASSERT_TRUE(p.load(forever_writer("t1", 1) + forever_writer("t2", 2) + forever_writer("t3", 3)));
  p.d.start(1, "t1");
  p.d.start(3, "t3");
  p.run(4);
  EXPECT_EQ(p.turns, repeat({1, 3}, 2));
  p.d.start(2, "t2");
  p.run(4);
  EXPECT_EQ(p.turns, concat({repeat({1, 3}, 2), {1, 2, 3, 1}}));
}

TEST(PhaseRoundRobin, AConditionWaitSpendsItsTurn) {
  Phases p;
  ASSERT_TRUE(p.load(forever_writer("t1", 1) + forever_writer("t3", 3) + R"(
.routine task "t2" in=0 out=0 entry=t2
t2:
  CMDGET 1 0
  JNZ go
  YIELD
  JMP t2
go:
  PUSHI 2
  CMDSET 1 0
  JMP.eol go
)"));
  p.d.start(1, "t1");
  p.d.start(2, "t2");
  p.d.start(3, "t3");
  p.run(6);
  EXPECT_EQ(p.turns, repeat({1, 2, 3}, 2));  // task 2's turns pass in its `till`
  EXPECT_EQ(p.d.take_trace(), (std::vector<int32_t>{1, 3, 1, 3}));
  p.d.host.registers[0] = Value::of_int(1);
  p.run(3);
  EXPECT_EQ(p.d.take_trace(), (std::vector<int32_t>{1, 2, 3}));
}

TEST(PhaseRoundRobin, ASleepIsOutOfTurnUntilItsTime) {
  Phases p;
  ASSERT_TRUE(p.load(forever_writer("t1", 1) + forever_writer("t3", 3) + routine_header("t2") +
                     write_line(2) + sleep_line(1) + write_forever("t2_loop", 20)));
  p.d.start(1, "t1");
  p.d.start(2, "t2");
  p.d.start(3, "t3");
  // Phase 4 (200 µs): task 2 begins `sleep 1`, its command's one phase; it wakes at 1200 µs,
  // phase 24, which is task 1's turn; phase 25 is task 2's, running the command after the sleep.
  p.run(29);
  EXPECT_EQ(p.turns, concat({{1, 2, 3, 1, 2}, repeat({3, 1}, 10), {2, 3, 1, 2}}));
  std::vector<int32_t> trace{1, 2, 3, 1};
  for (int i = 0; i < 10; ++i) trace.insert(trace.end(), {3, 1});
  trace.insert(trace.end(), {20, 3, 1, 20});
  EXPECT_EQ(p.d.take_trace(), trace);
}

TEST(PhaseRoundRobin, ALockGivesItsHolderEveryPhaseFromTheNext) {
  Phases p;
  ASSERT_TRUE(p.load(routine_header("t1") + write_line(1) + action_line(kLock) + write_line(11) +
                     write_line(12) + action_line(kUnlock) + write_forever("t1_loop", 1) +
                     forever_writer("t2", 2) + forever_writer("t3", 3)));
  for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
  p.run(4);
  EXPECT_EQ(p.policy.lock_holder(), 1u);
  p.run(6);
  EXPECT_EQ(p.turns, (std::vector<uint32_t>{1, 2, 3, 1, 1, 1, 1, 2, 3, 1}));
  EXPECT_EQ(p.d.take_trace(), (std::vector<int32_t>{1, 2, 3, 11, 12, 2, 3, 1}));
  EXPECT_EQ(p.policy.lock_holder(), kNone);
}

TEST(PhaseRoundRobin, ExtraLocksDoNotNestAndOneUnlockFrees) {
  Phases p;
  ASSERT_TRUE(p.load(routine_header("t1") + action_line(kLock) + action_line(kLock) +
                     write_line(11) + action_line(kUnlock) + write_forever("t1_loop", 1) +
                     forever_writer("t2", 2) + forever_writer("t3", 3)));
  for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
  p.run(7);
  EXPECT_EQ(p.turns, (std::vector<uint32_t>{1, 1, 1, 1, 2, 3, 1}));
  EXPECT_EQ(p.policy.lock_holder(), kNone);
}

TEST(PhaseRoundRobin, OnlyTheHoldersUnlockCountsAndALockWhileHeldIsIgnored) {
  PhaseRoundRobin policy;
  policy.unlock(2);  // stray: nothing is held
  EXPECT_EQ(policy.lock_holder(), kNone);
  policy.lock(0);  // task 0 takes no turns, so it cannot hold the lock
  policy.lock(4);  // not a task
  EXPECT_EQ(policy.lock_holder(), kNone);
  policy.lock(1);
  policy.lock(3);
  EXPECT_EQ(policy.lock_holder(), 1u);
  policy.unlock(2);
  EXPECT_EQ(policy.lock_holder(), 1u);
  policy.unlock(1);
  EXPECT_EQ(policy.lock_holder(), kNone);
}

TEST(PhaseRoundRobin, TheHoldersEndReleasesTheLock) {
  Phases p;
  ASSERT_TRUE(p.load(routine_header("t1") + action_line(kLock) + write_line(11) + "  RET\n" +
                     forever_writer("t2", 2) + forever_writer("t3", 3)));
  for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
  p.phase();
  const PhaseResult last = p.phase();
  EXPECT_TRUE(last.report.has(1, ThreadEvent::Finished));  // with its last command
  p.run(3);
  EXPECT_EQ(p.turns, (std::vector<uint32_t>{1, 1, 2, 3, 2}));
  EXPECT_EQ(p.policy.lock_holder(), kNone);
}

TEST(PhaseRoundRobin, OthersSleepsKeepCountingUnderTheLock) {
  std::string t1 = routine_header("t1") + write_line(1) + action_line(kLock);
  for (int i = 0; i < 30; ++i) t1 += write_line(11);
  t1 += action_line(kUnlock) + write_forever("t1_loop", 1);
  Phases p;
  ASSERT_TRUE(p.load(t1 + routine_header("t2") + sleep_line(1) + write_forever("t2_loop", 20) +
                     forever_writer("t3", 3)));
  for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
  // Task 2 sleeps at phase 1 (50 µs) until 1050 µs, during the lock (phases 4..34); it runs
  // in the first turn after the unlock.
  p.run(38);
  EXPECT_EQ(p.turns, concat({{1, 2, 3, 1}, repeat({1}, 31), {2, 3, 1}}));
  const std::vector<int32_t> trace = p.d.take_trace();
  ASSERT_EQ(trace.size(), 35u);
  EXPECT_EQ(trace[32], 20);
}

TEST(PhaseRoundRobin, AHolderThatSleepsKeepsTheLockAndThePhasesPassIdle) {
  Phases p;
  ASSERT_TRUE(p.load(routine_header("t1") + action_line(kLock) + sleep_line(1) + write_line(11) +
                     action_line(kUnlock) + write_forever("t1_loop", 1) + forever_writer("t2", 2) +
                     forever_writer("t3", 3)));
  for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
  // The sleep begins at phase 1 (50 µs) and ends at 1050 µs, phase 21.
  p.run(25);
  EXPECT_EQ(p.turns, concat({{1, 1}, repeat({kNone}, 19), {1, 1, 2, 3}}));
  EXPECT_EQ(p.d.take_trace(), (std::vector<int32_t>{11, 2, 3}));
}

TEST(PhaseRoundRobin, ARunTimeErrorStopsThatTaskOnly) {
  Phases p;
  ASSERT_TRUE(p.load(forever_writer("t1", 1) + forever_writer("t3", 3) + routine_header("t2") +
                     write_line(2) + "  PUSHI 1\n  PUSHI 0\n  DIVI\n  POP\n  EOL\n  RET\n"));
  for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
  p.run(4);
  const PhaseResult failed = p.phase();
  EXPECT_EQ(failed.turn, 2u);
  EXPECT_TRUE(failed.report.has(2, ThreadEvent::Error));
  p.run(4);
  EXPECT_EQ(p.turns, (std::vector<uint32_t>{1, 2, 3, 1, 2, 3, 1, 3, 1}));
  EXPECT_EQ(p.d.machine.last_error(2), vm::RunError::DivisionByZero);
}

TEST(PhaseRoundRobin, AnIdleDriveHasNothingToDo) {
  Phases p;
  ASSERT_TRUE(p.load(forever_writer("t1", 1)));
  for (int i = 0; i < 1000; ++i) {
    const PhaseResult r = p.phase();
    ASSERT_EQ(r.turn, kNone);
    ASSERT_TRUE(r.report.empty());
  }
  // A halted task is not active either.
  p.d.start(1, "t1");
  p.d.machine.halt(1);
  EXPECT_EQ(p.phase().turn, kNone);
  EXPECT_TRUE(p.d.take_trace().empty());
}

TEST(PhaseRoundRobin, SameInputsSameTurnsBitForBit) {
  const auto scenario = [](std::vector<uint32_t>& turns, std::vector<int32_t>& trace) {
    Phases p;
    std::string t1 = routine_header("t1") + write_line(1) + action_line(kLock);
    for (int i = 0; i < 7; ++i) t1 += write_line(11);
    t1 += sleep_line(1) + action_line(kUnlock) + write_forever("t1_loop", 1);
    ASSERT_TRUE(p.load(t1 + routine_header("t2") + sleep_line(2) + write_forever("t2_loop", 2) +
                       R"(
.routine task "t3" in=0 out=0 entry=t3
t3:
  CMDGET 1 0
  JNZ t3_go
  YIELD
  JMP t3
t3_go:
  PUSHI 3
  CMDSET 1 0
  JMP.eol t3_go
)"));
    for (uint32_t t = 1; t <= 3; ++t) p.d.start(t, "t" + std::to_string(t));
    p.run(50);
    p.d.host.registers[0] = Value::of_int(1);
    p.run(100);
    turns = p.turns;
    trace = p.d.take_trace();
  };
  std::vector<uint32_t> turns_a, turns_b;
  std::vector<int32_t> trace_a, trace_b;
  scenario(turns_a, trace_a);
  scenario(turns_b, trace_b);
  EXPECT_EQ(turns_a, turns_b);
  EXPECT_EQ(trace_a, trace_b);
  EXPECT_EQ(turns_a.size(), 150u);
}

}  // namespace
}  // namespace uprog::test
