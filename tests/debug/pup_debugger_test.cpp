// The debugger on the AG300's PUP (tests/debug/programs/two_threads.pup): a breakpoint at a PUP
// source line through the debug map, threads 1..8 by name, the #definevar variables, a PUP
// expression, stepping one thread while the other stays halted, and a step out of a function.
#include <gtest/gtest.h>

#include <filesystem>

#include "debug/debugger.h"
#include "dialects/pup/dialect.h"

namespace uprog::debug {
namespace {

const std::string kProgram = UPROG_SOURCE_DIR "/tests/debug/programs/two_threads.pup";
constexpr uint64_t kSecond = 1'000'000'000;
constexpr uint32_t kThread1 = 1, kThread2 = 2;  // the VM's threads are the AG300's, 1..8

struct Session {
  controller::Controller drive{[] {
    controller::ControllerOptions o;
    o.dialect = &pup::dialect();
    return o;
  }()};
  Debugger debugger{drive};

  explicit Session(const std::string& program = kProgram) {
    std::vector<Diagnostic> diagnostics;
    EXPECT_TRUE(drive.download_source_file(program, diagnostics));
    EXPECT_EQ(drive.start_program(""), "");
    debugger.program_changed();
  }
  std::string global(const std::string& name) const {
    for (const Variable& v : debugger.globals())
      if (v.name == name) return v.value;
    return "<none>";
  }
  int count(const std::string& name) const { return std::stoi(global(name)); }
  uint32_t line(uint32_t thread) const { return debugger.stack(thread).at(0).line; }
  RunState step(uint32_t thread, bool single_thread) {
    debugger.step(thread, StepKind::Over, single_thread);
    return debugger.run(kSecond);
  }
};

BreakpointSpec at(uint32_t line) {
  BreakpointSpec b;
  b.line = line;
  return b;
}

TEST(PupDebugger, StopsAtAPupSourceLineInTheThreadThatRunsIt) {
  Session s;
  const auto states = s.debugger.set_line_breakpoints(kProgram, {at(12)});
  ASSERT_TRUE(states.at(0).verified) << states[0].message;
  EXPECT_EQ(states[0].line, 12u);
  EXPECT_EQ(std::filesystem::path(states[0].file).filename(), "two_threads.pup");
  ASSERT_EQ(s.debugger.run(kSecond), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Breakpoint);
  EXPECT_EQ(s.debugger.last_stop().thread, kThread2);
  const auto frames = s.debugger.stack(kThread2);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].routine, "task 2");
  EXPECT_EQ(frames[0].line, 12u);
  // Thread 1 is halted where it stood, in its own loop.
  const uint32_t one_at = s.line(kThread1);
  EXPECT_TRUE(one_at == 7 || one_at == 8 || one_at == 9) << one_at;
}

TEST(PupDebugger, ThreadsOneToEightByName) {
  Session s;
  const auto threads = s.debugger.threads();
  ASSERT_EQ(threads.size(), 8u);
  for (uint32_t t = 1; t <= 8; ++t) {
    EXPECT_EQ(threads[t - 1].thread, t);
    EXPECT_EQ(threads[t - 1].name, "thread " + std::to_string(t));
  }
}

TEST(PupDebugger, VariablesByTheirNamesAndPupExpressions) {
  Session s;
  s.debugger.set_line_breakpoints(kProgram, {at(12)});
  ASSERT_EQ(s.debugger.run(kSecond), RunState::Stopped);
  EXPECT_EQ(s.count("Two"), 0);  // stopped before thread 2's first count
  // The breakpoint again, one round of thread 2's loop later: Two counted once, and thread 1
  // (a CUP line a cycle, as thread 2) has counted too.
  s.debugger.resume();
  ASSERT_EQ(s.debugger.run(kSecond), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().thread, kThread2);
  const int one = s.count("One");
  EXPECT_EQ(s.count("Two"), 1);
  EXPECT_GE(one, 1);
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "Two + 1").value, "2");
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "One * 2 + AGenData[2]").value,
            std::to_string(one * 2 + 1));
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "One == Two").is_true, one == 1);
  EXPECT_TRUE(s.debugger.evaluate(kThread2, 0, "Two == 1").is_true);
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "abs(0 - One)").value, std::to_string(one));
  const dialect::Evaluation zero = s.debugger.evaluate(kThread2, 0, "One / (Two - 1)");
  EXPECT_FALSE(zero.ok);
  EXPECT_EQ(zero.error, "controller error 30");
  // && and || as the program computes them: the right side only when the left does not decide
  // (Two is 1, so the division by Two - 1 would be error 30).
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "Two == 0 && One / (Two - 1) > 0").value, "0");
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "Two == 1 || One / (Two - 1) > 0").value, "1");
  // AGetStatus[1], motion ended: the drive has not moved
  EXPECT_EQ(s.debugger.evaluate(kThread2, 0, "AGetStatus[1]").value, "1");
  const dialect::Evaluation bad = s.debugger.evaluate(kThread2, 0, "One +");
  EXPECT_FALSE(bad.ok);
  EXPECT_FALSE(bad.error.empty());
}

// singleThread: thread 2 steps round its loop, thread 1 stays halted (its count does not move);
// without it, thread 1 runs on while thread 2 steps.
TEST(PupDebugger, SteppingOneThreadLeavesTheOtherHalted) {
  Session s;
  s.debugger.set_line_breakpoints(kProgram, {at(12)});
  ASSERT_EQ(s.debugger.run(kSecond), RunState::Stopped);
  s.debugger.clear_breakpoints();
  const int one = s.count("One");
  const uint32_t one_at = s.line(kThread1);
  std::vector<uint32_t> lines;
  for (int i = 0; i < 6; ++i) {
    ASSERT_EQ(s.step(kThread2, true), RunState::Stopped);
    EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Step);
    EXPECT_EQ(s.debugger.last_stop().thread, kThread2);
    lines.push_back(s.line(kThread2));
  }
  EXPECT_EQ(s.count("One"), one);
  EXPECT_EQ(s.line(kThread1), one_at);
  EXPECT_EQ(vm::ThreadStatus::Halted, s.debugger.threads()[0].status);
  // Round the loop line by line: each step that started at line 12 counted once (the first
  // started there, at the breakpoint; the last stop has not run its line yet).
  int passes = 1;
  for (size_t i = 0; i + 1 < lines.size(); ++i) passes += lines[i] == 12 ? 1 : 0;
  EXPECT_GE(passes, 2) << ::testing::PrintToString(lines);
  EXPECT_EQ(s.count("Two"), passes) << ::testing::PrintToString(lines);
  // All threads: thread 1 counts on while thread 2 takes one step.
  ASSERT_EQ(s.step(kThread2, false), RunState::Stopped);
  EXPECT_GT(s.count("One"), one);
}

// examples/pup/library_user.pup: task 1 calls MOVE_TO (line 10), which calls WAIT_SETTLED. A step
// out of MOVE_TO's line 21 returns to the task after its call, at line 11, and the program goes on.
TEST(PupDebugger, StepOutOfAFunctionReturnsAfterItsCall) {
  const std::string program = UPROG_SOURCE_DIR "/examples/pup/library_user.pup";
  Session s(program);
  ASSERT_TRUE(s.debugger.set_line_breakpoints(program, {at(21)}).at(0).verified);
  ASSERT_EQ(s.debugger.run(kSecond), RunState::Stopped);
  EXPECT_EQ(s.line(kThread1), 21u);
  EXPECT_EQ(s.debugger.threads().at(0).where, "library_user.pup:21");  // the source's line too
  s.debugger.set_line_breakpoints(program, {});
  s.debugger.step(kThread1, StepKind::Out, true);
  ASSERT_EQ(s.debugger.run(kSecond), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Step);
  EXPECT_EQ(s.line(kThread1), 11u);
  EXPECT_EQ(s.count("Moves"), 1);
}

}  // namespace
}  // namespace uprog::debug
