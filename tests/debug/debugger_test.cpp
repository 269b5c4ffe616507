// The drive-side debugger on a Gold program (tests/debug/programs/scenario.ehl): line and
// function breakpoints, conditions and hit counts, stepping by source line, frames, locals,
// globals, signals, setting a variable, break on a run-time error, and time standing still.
#include "debug/debugger.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "dialects/gold/dialect.h"

namespace uprog::debug {
namespace {

const std::string kScenario = UPROG_SOURCE_DIR "/tests/debug/programs/scenario.ehl";
constexpr uint64_t kSecond = 1'000'000'000;

BreakpointSpec at(uint32_t line, std::string condition = {}, std::string hit = {},
                  std::string log = {}) {
  BreakpointSpec b;
  b.line = line;
  b.condition = std::move(condition);
  b.hit_condition = std::move(hit);
  b.log_message = std::move(log);
  return b;
}

BreakpointSpec function(std::string name) {
  BreakpointSpec b;
  b.function = std::move(name);
  return b;
}

struct Session {
  controller::Controller drive{[] {
    controller::ControllerOptions o;
    o.dialect = &gold::dialect();
    return o;
  }()};
  Debugger debugger{drive};

  explicit Session(const std::string& file = kScenario) {
    std::vector<Diagnostic> diagnostics;
    EXPECT_TRUE(drive.download_source_file(file, diagnostics));
    EXPECT_EQ(drive.start_program(""), "");
    debugger.program_changed();
  }
  uint32_t line() const { return debugger.stack(0).at(0).line; }
  std::string routine() const { return debugger.stack(0).at(0).routine; }
  std::string local(const std::string& name, uint32_t depth = 0) const {
    for (const Variable& v : debugger.locals(0, depth))
      if (v.name == name) return v.value;
    return "<none>";
  }
  std::string global(const std::string& name) const {
    for (const Variable& v : debugger.globals())
      if (v.name == name) return v.value;
    return "<none>";
  }
  RunState run() { return debugger.run(kSecond); }
  RunState step(StepKind k) {
    debugger.step(0, k);
    return run();
  }
  RunState go() {
    debugger.resume();
    return run();
  }
};

TEST(Debugger, LineBreakpointStopsBeforeTheLineRuns) {
  Session s;
  const auto states = s.debugger.set_line_breakpoints(kScenario, {at(19)});
  ASSERT_EQ(states.size(), 1u);
  EXPECT_TRUE(states[0].verified);
  EXPECT_EQ(states[0].line, 19u);
  ASSERT_EQ(s.run(), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Breakpoint);
  EXPECT_EQ(s.debugger.last_stop().breakpoints, std::vector<uint32_t>{states[0].id});
  EXPECT_EQ(s.routine(), "add");
  EXPECT_EQ(s.line(), 19u);
  // First call: add(0, 1); line 18 ran (c = 1), line 19 (s = c) not yet.
  EXPECT_EQ(s.local("a"), "0");
  EXPECT_EQ(s.local("b"), "1");
  EXPECT_EQ(s.local("c"), "1");
  EXPECT_EQ(s.local("s"), "0");
  // The caller's frame: main at line 11, its loop counter.
  const auto stack = s.debugger.stack(0);
  ASSERT_EQ(stack.size(), 2u);
  EXPECT_EQ(stack[1].routine, "main");
  EXPECT_EQ(stack[1].line, 11u);
  EXPECT_EQ(s.local("i", 1), "1");
  EXPECT_EQ(s.global("divisor"), "4");
}

// main's `for i = 1:5` keeps its bound in a compiler temporary ($t0 in the image): the Locals
// show what the program declared, i alone.
TEST(Debugger, LocalsAreWhatTheProgramDeclared) {
  Session s;
  s.debugger.set_line_breakpoints(kScenario, {at(10)});
  ASSERT_EQ(s.run(), RunState::Stopped);
  const std::vector<Variable> locals = s.debugger.locals(0, 0);
  ASSERT_EQ(locals.size(), 1u);
  EXPECT_EQ(locals[0].name, "i");
  EXPECT_EQ(s.debugger.globals().size(), 3u);  // total, divisor, ratio
}

TEST(Debugger, ALineWithoutCodeMovesToTheNextLineWithCode) {
  Session s;
  const auto states = s.debugger.set_line_breakpoints(kScenario, {at(16), at(1), at(99)});
  EXPECT_TRUE(states[0].verified);
  EXPECT_EQ(states[0].line, 18u);  // the blank and the declarations before it have no code
  EXPECT_EQ(states[1].line, 9u);
  EXPECT_FALSE(states[2].verified);
}

TEST(Debugger, ContinueRunsToTheNextHitAndToTheEnd) {
  Session s;
  s.debugger.set_line_breakpoints(kScenario, {at(11)});
  for (int i = 1; i <= 5; ++i) {
    ASSERT_EQ(s.run(), RunState::Stopped) << i;
    EXPECT_EQ(s.local("i"), std::to_string(i));
    s.debugger.resume();
  }
  EXPECT_EQ(s.run(), RunState::Ended);
  EXPECT_EQ(s.global("total"), "15");
  EXPECT_EQ(s.global("ratio"), "25.0");
}

TEST(Debugger, HitConditionsCountHits) {
  struct Case {
    std::string hit;
    std::vector<std::string> stops;  // i at each stop
  };
  for (const Case& c :
       {Case{"3", {"3"}}, Case{"==2", {"2"}}, Case{"%2", {"2", "4"}}, Case{">=4", {"4", "5"}}}) {
    Session s;
    s.debugger.set_line_breakpoints(kScenario, {at(11, {}, c.hit)});
    std::vector<std::string> stops;
    while (s.run() == RunState::Stopped) {
      stops.push_back(s.local("i"));
      s.debugger.resume();
    }
    EXPECT_EQ(stops, c.stops) << c.hit;
  }
  Session s;
  const auto bad = s.debugger.set_line_breakpoints(kScenario, {at(11, {}, "<3")});
  EXPECT_FALSE(bad[0].verified);
  EXPECT_NE(bad[0].message.find("hit count"), std::string::npos);
}

TEST(Debugger, AConditionInGoldSyntaxSeesLocalsAndGlobals) {
  Session s;
  s.debugger.set_line_breakpoints(kScenario, {at(18, "a + b == 6 && divisor == 4")});
  ASSERT_EQ(s.run(), RunState::Stopped);
  EXPECT_EQ(s.local("a"), "3");  // the third call: add(3, 3)
  EXPECT_EQ(s.local("b"), "3");
  s.debugger.resume();
  EXPECT_EQ(s.run(), RunState::Ended);
}

TEST(Debugger, ALogMessageLogsInsteadOfStopping) {
  Session s;
  s.debugger.set_line_breakpoints(kScenario, {at(19, {}, {}, "c={c} total={total}")});
  EXPECT_EQ(s.run(), RunState::Ended);
  EXPECT_EQ(s.debugger.take_messages(),
            (std::vector<std::string>{"c=1 total=0", "c=3 total=1", "c=6 total=3", "c=10 total=6",
                                      "c=15 total=10"}));
}

TEST(Debugger, FunctionBreakpointStopsAtItsFirstLine) {
  Session s;
  const auto states = s.debugger.set_function_breakpoints({function("add"), function("nothere")});
  ASSERT_EQ(states.size(), 2u);
  EXPECT_TRUE(states[0].verified);
  EXPECT_FALSE(states[1].verified);
  ASSERT_EQ(s.run(), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::FunctionBreakpoint);
  EXPECT_EQ(s.routine(), "add");
  EXPECT_EQ(s.line(), 18u);
}

TEST(Debugger, StepsByLineOverIntoAndOut) {
  Session s;
  s.debugger.stop_at_entry();
  EXPECT_EQ(s.line(), 9u);
  EXPECT_EQ(s.step(StepKind::Over), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Step);
  EXPECT_EQ(s.line(), 10u);
  s.step(StepKind::Over);
  EXPECT_EQ(s.line(), 11u);  // the loop's test ran on; the step stops where line 11 starts
  s.step(StepKind::In);
  EXPECT_EQ(s.routine(), "add");
  EXPECT_EQ(s.line(), 18u);
  s.step(StepKind::Over);
  EXPECT_EQ(s.line(), 19u);
  EXPECT_EQ(s.local("c"), "1");
  s.step(StepKind::Out);
  EXPECT_EQ(s.routine(), "main");
  EXPECT_EQ(s.line(), 12u);
  EXPECT_EQ(s.global("total"), "1");
  s.step(StepKind::Over);  // `end` jumps back to the loop's test and into the body
  EXPECT_EQ(s.line(), 11u);
  EXPECT_EQ(s.local("i"), "2");
  s.step(StepKind::Over);  // over the call: add's lines run, the step stops after it
  EXPECT_EQ(s.routine(), "main");
  EXPECT_EQ(s.line(), 12u);
  EXPECT_EQ(s.global("total"), "3");
  EXPECT_EQ(s.go(), RunState::Ended);
}

TEST(Debugger, EachSteppedLineTakesOneCycleAndPausedTimeStandsStill) {
  Session s;
  s.debugger.stop_at_entry();
  const uint64_t t0 = s.drive.now_ns();
  const uint64_t cycle = s.drive.firmware().cycle_ns();
  EXPECT_EQ(s.debugger.run(kSecond), RunState::Stopped);  // stopped: run() lets no time pass
  EXPECT_EQ(s.drive.now_ns(), t0);
  s.step(StepKind::Over);
  EXPECT_EQ(s.drive.now_ns(), t0 + cycle);
}

TEST(Debugger, SetAVariableAndTheProgramUsesIt) {
  Session s;
  s.debugger.set_line_breakpoints(kScenario, {at(13)});
  ASSERT_EQ(s.run(), RunState::Stopped);
  const int divisor = s.debugger.find_global("divisor");
  ASSERT_GE(divisor, 0);
  EXPECT_FALSE(s.debugger.set_global(static_cast<uint32_t>(divisor), 0, "2.5").ok);  // an int
  EXPECT_EQ(s.debugger.set_global(static_cast<uint32_t>(divisor), 0, "8").value, "8");
  EXPECT_EQ(s.debugger.set_local(0, 0, "i", "-7").value, "-7");
  EXPECT_EQ(s.local("i"), "-7");
  EXPECT_FALSE(s.debugger.set_local(0, 0, "nothere", "1").ok);
  EXPECT_EQ(s.go(), RunState::Ended);
  EXPECT_EQ(s.global("ratio"), "12.0");  // 100 / 8, truncated
}

TEST(Debugger, BreaksOnARunTimeErrorKeepingTheFrames) {
  Session s;
  s.debugger.set_break_on_error(true);
  s.debugger.set_line_breakpoints(kScenario, {at(13)});
  ASSERT_EQ(s.run(), RunState::Stopped);
  s.debugger.set_global(static_cast<uint32_t>(s.debugger.find_global("divisor")), 0, "0");
  s.debugger.resume();
  ASSERT_EQ(s.run(), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Exception);
  EXPECT_NE(s.debugger.last_stop().description.find("ivision"), std::string::npos)
      << s.debugger.last_stop().description;
  EXPECT_EQ(s.line(), 13u);
  EXPECT_EQ(s.local("i"), "6");
  EXPECT_EQ(s.go(), RunState::Ended);
}

TEST(Debugger, EvaluatesGoldExpressionsInAFrame) {
  Session s;
  s.debugger.set_line_breakpoints(kScenario, {at(19)});
  ASSERT_EQ(s.run(), RunState::Stopped);
  EXPECT_EQ(s.debugger.evaluate(0, 0, "a + b * 10").value, "10");
  EXPECT_EQ(s.debugger.evaluate(0, 1, "i").value, "1");
  EXPECT_EQ(s.debugger.evaluate(0, 0, "divisor / 8.0").value, "0.500000");  // Gold shows a float so
  const auto bad = s.debugger.evaluate(0, 0, "a +");
  EXPECT_FALSE(bad.ok);
  EXPECT_FALSE(bad.error.empty());
  // An assignment in a watch stays assigned.
  EXPECT_TRUE(s.debugger.evaluate(0, 0, "c = 40").ok);
  EXPECT_EQ(s.local("c"), "40");
}

TEST(Debugger, PauseStopsEveryThreadWhereItStands) {
  Session s;
  s.debugger.pause();
  EXPECT_EQ(s.debugger.state(), RunState::Stopped);
  EXPECT_EQ(s.debugger.last_stop().reason, StopReason::Pause);
  EXPECT_EQ(s.debugger.threads().at(0).status, vm::ThreadStatus::Halted);
  EXPECT_EQ(s.go(), RunState::Ended);
}

TEST(Debugger, BreakpointsBeyondTheMachinesTableAreUnverified) {
  // A program of 30 lines with code; Gold's machine keeps 16 breakpoints.
  const std::string path = testing::TempDir() + "/thirty_lines.ehl";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("int n\nfunction main()\n", f);
    for (int i = 0; i < 30; ++i) std::fputs("n = n + 1\n", f);
    std::fputs("return\n", f);
    std::fclose(f);
  }
  Session s(path);
  std::vector<BreakpointSpec> specs;
  for (uint32_t line = 3; line < 33; ++line) specs.push_back(at(line));
  const auto states = s.debugger.set_line_breakpoints(path, specs);
  ASSERT_EQ(states.size(), 30u);
  size_t verified = 0;
  for (const BreakpointState& b : states) {
    if (b.verified)
      ++verified;
    else
      EXPECT_EQ(b.message, "the program's breakpoint table is full");
  }
  EXPECT_EQ(verified, 16u);
  // The ones set stop the program, line by line.
  ASSERT_EQ(s.run(), RunState::Stopped);
  EXPECT_EQ(s.line(), 3u);
}

TEST(Debugger, SignalsShowTheDrive) {
  Session s;
  const auto signals = s.debugger.signals();
  ASSERT_FALSE(signals.empty());
  EXPECT_EQ(signals[0].name, "position");
  EXPECT_EQ(signals[0].value, "0");
}

}  // namespace
}  // namespace uprog::debug
