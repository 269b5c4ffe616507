// Machine behaviour that a case file cannot express: slices and budgets, events, halting,
// breakpoints and single-step, several threads, loader and verifier refusals.
#include <gtest/gtest.h>

#include "bytecode/opcodes.h"
#include "vm_fixture.h"

namespace uprog::test {
namespace {

using vm::Budget;
using vm::SliceEnd;
using vm::ThreadStatus;

// A main that counts lines forever, and an event routine that marks that it ran.
const char* kCounter = R"(
.global int "lines" 1
.global int "events" 1
.routine function "main" in=0 out=0 entry=main
.routine auto "on_event" in=0 out=0 entry=on_event
main:
  LDG lines
  PUSHI 1
  ADDI
  STG lines
  EOL
  JMP main
on_event:
  LDG events
  PUSHI 1
  ADDI
  STG events
  EOL
  RET
)";

TEST(Machine, InstructionBudgetCountsExactly) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  ASSERT_EQ(p.machine.start(0, 0), vm::RunError::None);
  const auto r = p.machine.run_slice(0, Budget::of_instructions(13));
  EXPECT_EQ(r.end, SliceEnd::BudgetSpent);
  EXPECT_EQ(r.executed, 13u);
  // 6 instructions a loop (LDG PUSHI ADDI STG EOL JMP): 13 run two loops and one LDG.
  EXPECT_EQ(p.global("lines").i, 2);
  EXPECT_EQ(p.machine.pc(0), 1u);
}

TEST(Machine, LineBudgetStopsAfterEndOfLine) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  p.machine.start(0, 0);
  const auto r = p.machine.run_slice(0, Budget::of_lines(4));
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(p.global("lines").i, 4);
  EXPECT_EQ(p.machine.pc(0), 5u);  // just after EOL, at the JMP
}

// The line-end mark (OP.eol) ends a line as an EOL after the instruction would, without one.
TEST(Machine, LineEndMarkEndsTheLineAfterItsInstruction) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "lines" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG lines
  PUSHI 1
  ADDI
  STG.eol lines
  JMP main
)"));
  p.machine.start(0, 0);
  const auto r = p.machine.run_slice(0, Budget::of_lines(4));
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(r.lines, 4u);
  EXPECT_EQ(p.global("lines").i, 4);
  EXPECT_EQ(p.machine.pc(0), 4u);  // just after the marked store, at the JMP
  // Counted with an instruction budget too: the JMP, then one more line of four instructions.
  const auto counted = p.machine.run_slice(0, Budget{5, 10, 0});
  EXPECT_EQ(counted.end, SliceEnd::BudgetSpent);
  EXPECT_EQ(counted.executed, 5u);
  EXPECT_EQ(counted.lines, 1u);
  EXPECT_EQ(p.global("lines").i, 5);
}

// A marked branch ends its line on both paths; a marked host call that ends the slice ends
// its line too.
TEST(Machine, LineEndMarkOnABranchEndsTheLineEitherWay) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "n" 1
.global int "odd" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG n
  PUSHI 1
  ADDI
  STG n
  LDG n
  PUSHI 2
  REMI
  JZ.eol main
  PUSHI 100
  STG.eol odd
  JMP.eol main
)"));
  p.machine.start(0, 0);
  auto r = p.machine.run_slice(0, Budget::of_lines(1));  // n = 1: falls through
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(p.global("n").i, 1);
  EXPECT_EQ(p.machine.pc(0), 8u);
  r = p.machine.run_slice(0, Budget::of_lines(1));
  EXPECT_EQ(p.global("odd").i, 100);
  EXPECT_EQ(p.machine.pc(0), 10u);
  r = p.machine.run_slice(0, Budget::of_lines(1));  // the marked JMP is a line of its own
  EXPECT_EQ(p.machine.pc(0), 0u);
  EXPECT_EQ(p.global("n").i, 1);
  r = p.machine.run_slice(0, Budget::of_lines(1));  // n = 2: taken
  EXPECT_EQ(r.lines, 1u);
  EXPECT_EQ(p.global("n").i, 2);
  EXPECT_EQ(p.machine.pc(0), 0u);
}

// JLINES: a run of four one-instruction lines and its fused copy, which also counts its runs in
// `fast` so that the test sees which copy ran. B = 4: the run ends four lines; the copy's marked
// store counts one, its JMPLN the other three.
const char* kLineRun = R"(
.global int "a" 1
.global int "fast" 1
.routine function "main" in=0 out=0 entry=main
main:
  JLINES fused 4
  LDG.eol a
  PUSHI.eol 1
  ADDI.eol
  STG.eol a
next:
  JMP.eol main
fused:
  LDG fast
  PUSHI 1
  ADDI
  STG fast
  LDG a
  PUSHI 1
  ADDI
  STG.eol a
  JMPLN next 3
)";

TEST(Machine, LineRunTakesItsFusedCopyWhenNothingCanStopInside) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kLineRun));
  p.machine.start(0, 0);
  // Ten lines: two loops of five (the run's four and the JMP's), both through the fused copy.
  auto r = p.machine.run_slice(0, Budget::of_lines(10));
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(r.lines, 10u);
  EXPECT_EQ(p.global("a").i, 2);
  EXPECT_EQ(p.global("fast").i, 2);
  EXPECT_EQ(p.machine.pc(0), 0u);
  // Four lines left is not more than the run ends: the lines one by one, the slice ending after
  // the fourth, at `next`.
  r = p.machine.run_slice(0, Budget::of_lines(4));
  EXPECT_EQ(r.lines, 4u);
  EXPECT_EQ(p.global("a").i, 3);
  EXPECT_EQ(p.global("fast").i, 2);
  EXPECT_EQ(p.machine.pc(0), 6u);
  // One line at a time (the drive's cycle) never takes the copy.
  for (int i = 0; i < 5; ++i) p.machine.run_slice(0, Budget::of_lines(1));
  EXPECT_EQ(p.global("a").i, 4);
  EXPECT_EQ(p.global("fast").i, 2);
  EXPECT_EQ(p.machine.pc(0), 6u);
}

TEST(Machine, LineRunTakesTheLinesUnderACountOrABreakpoint) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kLineRun));
  p.machine.start(0, 0);
  // Counted: 6 instructions a loop (JLINES, the four lines, the JMP).
  auto r = p.machine.run_slice(0, Budget{12, 0, 0});
  EXPECT_EQ(r.executed, 12u);
  EXPECT_EQ(p.global("a").i, 2);
  EXPECT_EQ(p.global("fast").i, 0);
  // A breakpoint anywhere: the lines, so that one inside the run stops there.
  ASSERT_TRUE(p.machine.set_breakpoint(3));  // line 2 of the run, PUSHI
  r = p.machine.run_slice(0, Budget::of_lines(100));
  EXPECT_EQ(r.end, SliceEnd::Breakpoint);
  EXPECT_EQ(p.machine.pc(0), 3u);
  EXPECT_EQ(p.global("fast").i, 0);
  ASSERT_TRUE(p.machine.clear_breakpoint(3));
  p.machine.resume(0);
  // The run's last three lines and the JMP's, then a loop with five lines left: fused.
  r = p.machine.run_slice(0, Budget::of_lines(9));
  EXPECT_EQ(r.lines, 9u);
  EXPECT_EQ(p.global("a").i, 4);
  EXPECT_EQ(p.global("fast").i, 1);
}

// A loop's back edge from fused code to its own JLINES (the copy of a CUP loop) goes straight
// into the copy again when more lines are left than a path runs, and otherwise to the lines one
// by one. A path runs five lines: the store's mark counts one, the JMPLN four.
TEST(Machine, FusedLoopReentersItsCopyOnlyWithMoreLinesLeftThanAPathRuns) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "a" 1
.global int "fast" 1
.routine function "main" in=0 out=0 entry=main
main:
  JLINES fused 5
  LDG.eol a
  PUSHI.eol 1
  ADDI.eol
  STG.eol a
  JMP.eol main
fused:
  LDG fast
  PUSHI 1
  ADDI
  STG fast
  LDG a
  PUSHI 1
  ADDI
  STG.eol a
  JMPLN main 4
)"));
  p.machine.start(0, 0);
  // 11 lines: the copy twice (6 left, then 1), then one line, LDG's.
  auto r = p.machine.run_slice(0, Budget::of_lines(11));
  EXPECT_EQ(r.lines, 11u);
  EXPECT_EQ(p.global("a").i, 2);
  EXPECT_EQ(p.global("fast").i, 2);
  EXPECT_EQ(p.machine.pc(0), 3u);
  p.machine.start(0, 0);
  // 10 lines: the copy once, then exactly five left, which a path could spend: the lines.
  r = p.machine.run_slice(0, Budget::of_lines(10));
  EXPECT_EQ(r.lines, 10u);
  EXPECT_EQ(p.global("a").i, 4);
  EXPECT_EQ(p.global("fast").i, 3);
  EXPECT_EQ(p.machine.pc(0), 0u);
}

// A call counts as a jump back, so that a slice of a line budget and a cap on jumps back ends
// in a call tree that never jumps back (routines calling the next forward, as the fuzzer's
// recursive fib without a line did for 10 s). The slice ends at the callee's entry.
TEST(Machine, CallsCountAsJumpsBack) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "calls" 1
.routine function "main" in=0 out=0 entry=main
.routine function "f" in=0 out=0 entry=f
main:
  CALL f 0
  CALL f 0
  CALL f 0
  RET
f:
  LDG calls
  PUSHI 1
  ADDI
  STG calls
  RET
)"));
  p.machine.start(0, 0);
  auto r = p.machine.run_slice(0, Budget{0, 100, 2});
  EXPECT_EQ(r.end, SliceEnd::BudgetSpent);
  EXPECT_EQ(p.global("calls").i, 1);  // the second call spent the budget, at f's entry
  EXPECT_EQ(p.machine.pc(0), 7u);
  EXPECT_EQ(p.machine.frame_count(0), 2u);
  r = p.machine.run_slice(0, Budget{0, 100, 2});
  EXPECT_EQ(r.end, SliceEnd::Finished);  // the second's body, then the third call: one of two
  EXPECT_EQ(p.global("calls").i, 3);
}

// CALLFEOL ends its line before the callee's first instruction: a slice of one line stops at the
// callee's entry, the frame made and the argument stored; the call counts as a jump back too.
TEST(Machine, MemoryFrameCallEndsItsLineAtTheCalleesEntry) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "mem" 8
.global int "done" 1
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=2 out=0 entry=proc
.local int "sp"
.local int "fp"
main:
  PUSHI 8
  STL 1
  PUSHI 5
  CALLFEOL proc 2101251  ; 3 words, 1 argument into word 2
  LDG done
  PUSHI 1
  ADDI
  STG done
  EOL
  RET
proc:
  EOL
  RET
)"));
  p.machine.start(0, 0);
  auto r = p.machine.run_slice(0, Budget::of_lines(1));
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(r.lines, 1u);
  EXPECT_EQ(p.machine.pc(0), 11u);  // proc's EOL
  EXPECT_EQ(p.machine.frame_count(0), 2u);
  EXPECT_EQ(p.machine.memory()[2].i, 5);
  r = p.machine.run_slice(0, Budget::of_lines(1));
  EXPECT_EQ(r.end, SliceEnd::LineEnd);  // proc's line
  EXPECT_EQ(p.global("done").i, 0);
  p.machine.start(0, 0);
  r = p.machine.run_slice(0, Budget{0, 100, 1});
  EXPECT_EQ(r.end, SliceEnd::BudgetSpent);  // the call spent the one jump back, at proc's entry
  EXPECT_EQ(p.machine.pc(0), 11u);
}

// JMPLN counts the lines of the path that leaves fused code; when they spend the slice's line
// budget (a copy whose JLINES promised fewer, which the loader never makes), the slice ends
// where it jumps to.
TEST(Machine, LeavingFusedCodeCountsItsLines) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "a" 1
.routine function "main" in=0 out=0 entry=main
main:
  JLINES fused 1
  LDG.eol a
  PUSHI.eol 1
  ADDI.eol
  STG.eol a
next:
  JMP.eol main
fused:
  LDG a
  PUSHI 1
  ADDI
  STG a
  JMPLN next 4
)"));
  p.machine.start(0, 0);
  auto r = p.machine.run_slice(0, Budget::of_lines(7));  // five lines a loop
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(r.lines, 7u);
  EXPECT_EQ(p.global("a").i, 2);
  EXPECT_EQ(p.machine.pc(0), 6u);  // at `next`: the second JMPLN spent the last two lines
  r = p.machine.run_slice(0, Budget::of_lines(5));
  EXPECT_EQ(r.lines, 5u);
  EXPECT_EQ(p.global("a").i, 3);
  EXPECT_EQ(p.machine.pc(0), 6u);
}

TEST(Machine, LineEndMarkOnAHostCallThatEndsTheSlice) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  CMDSET.eol 4 0
  PUSHI 2
  CMDSET.eol 1 0
  RET
)"));
  p.machine.start(0, 0);
  const auto r = p.machine.run_slice(0, Budget::of_lines(5));
  EXPECT_EQ(r.end, SliceEnd::Yielded);  // command 4 ends the slice
  EXPECT_EQ(r.lines, 1u);
  EXPECT_EQ(p.machine.pc(0), 3u);
}

TEST(Machine, EventInterruptsAndReturnsWhereItWas) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  p.machine.start(0, 0);
  p.machine.run_slice(0, Budget::of_lines(2));
  const uint32_t pc_before = p.machine.pc(0);
  ASSERT_EQ(p.machine.interrupt(0, 1), vm::RunError::None);
  EXPECT_EQ(p.machine.frame_count(0), 2u);
  EXPECT_TRUE(p.machine.frame(0, 0).is_event);
  p.machine.run_slice(0, Budget::of_lines(1));  // the event routine's one line
  EXPECT_EQ(p.global("events").i, 1);
  EXPECT_EQ(p.machine.frame_count(0), 2u);
  p.machine.run_slice(0, Budget::of_instructions(1));  // RET back
  EXPECT_EQ(p.machine.frame_count(0), 1u);
  EXPECT_EQ(p.machine.pc(0), pc_before);
  EXPECT_EQ(p.global("lines").i, 2);
  p.machine.run_slice(0, Budget::of_lines(1));
  EXPECT_EQ(p.global("lines").i, 3);
}

TEST(Machine, EventOnIdleThreadStartsIt) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  ASSERT_EQ(p.machine.interrupt(0, 1), vm::RunError::None);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
  EXPECT_EQ(p.global("events").i, 1);
  EXPECT_EQ(p.machine.status(0), ThreadStatus::Idle);
}

TEST(Machine, HaltResumeAndKill) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  p.machine.start(0, 0);
  p.machine.run_slice(0, Budget::of_lines(1));
  p.machine.halt(0);
  EXPECT_EQ(p.machine.status(0), ThreadStatus::Halted);
  EXPECT_EQ(p.machine.run_slice(0, Budget::of_lines(5)).end, SliceEnd::Halted);
  EXPECT_EQ(p.global("lines").i, 1);
  p.machine.resume(0);
  p.machine.run_slice(0, Budget::of_lines(1));
  EXPECT_EQ(p.global("lines").i, 2);
  p.machine.kill(0);
  EXPECT_EQ(p.machine.status(0), ThreadStatus::Idle);
  EXPECT_EQ(p.machine.run_slice(0, Budget::of_lines(1)).end, SliceEnd::NotRunning);
}

// A halted thread's stack is readable, and its pc moves only where the routine's own paths
// arrive with the stack as deep as it is now.
TEST(Machine, OperandStackAndMovingAHaltedThread) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "sum" 1
.routine function "main" in=0 out=0 entry=main
.routine function "other" in=0 out=0 entry=other
main:
  PUSHI 7
  PUSHI 9
  EOL
  ADDI
  STG sum
  EOL
  RET
other:
  RET
)"));
  // main's code words: PUSHI 7 (0), PUSHI 9 (1), EOL (2), ADDI (3), STG sum (4), EOL (5), RET (6).
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(p.machine.image()) / 4 + 1);
  const size_t size = scratch.size() * 4;
  p.machine.start(0, 0);
  EXPECT_FALSE(p.machine.move_pc(0, 2, scratch.data(), size));  // running: not moved
  p.machine.run_slice(0, Budget::of_lines(1));
  p.machine.halt(0);
  const auto stack = p.machine.operand_stack(0);
  ASSERT_EQ(stack.size(), 2u);
  EXPECT_EQ(stack[0].i, 7);
  EXPECT_EQ(stack[1].i, 9);
  EXPECT_FALSE(p.machine.move_pc(0, 5, scratch.data(), size));  // entered with nothing
  EXPECT_FALSE(p.machine.move_pc(0, 7, scratch.data(), size));  // other's
  EXPECT_FALSE(p.machine.move_pc(0, 2, scratch.data(), 4));     // too little scratch
  EXPECT_EQ(p.machine.pc(0), 3u);
  ASSERT_TRUE(p.machine.move_pc(0, 2, scratch.data(), size));  // the EOL, entered with both
  EXPECT_EQ(p.machine.pc(0), 2u);
  p.machine.resume(0);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Finished);
  EXPECT_EQ(p.global("sum").i, 16);
  EXPECT_TRUE(p.machine.operand_stack(0).empty());
}

TEST(Machine, BreakpointStopsAndContinues) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  ASSERT_TRUE(p.machine.set_breakpoint(3));  // the STG
  EXPECT_FALSE(p.machine.set_breakpoint(1000));
  p.machine.start(0, 0);
  auto r = p.machine.run_slice(0, Budget::unlimited());
  EXPECT_EQ(r.end, SliceEnd::Breakpoint);
  EXPECT_EQ(p.machine.pc(0), 3u);
  EXPECT_EQ(p.global("lines").i, 0);  // stopped before the store
  p.machine.resume(0);
  r = p.machine.run_slice(0, Budget::unlimited());
  EXPECT_EQ(r.end, SliceEnd::Breakpoint);  // around the loop once
  EXPECT_EQ(p.global("lines").i, 1);
  ASSERT_TRUE(p.machine.clear_breakpoint(3));
  p.machine.resume(0);
  p.machine.run_slice(0, Budget::of_lines(2));
  EXPECT_EQ(p.global("lines").i, 3);
}

TEST(Machine, SingleStepIsABudgetOfOne) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  p.machine.start(0, 0);
  for (uint32_t i = 1; i <= 4; ++i) {
    EXPECT_EQ(p.machine.run_slice(0, Budget::of_instructions(1)).executed, 1u);
    EXPECT_EQ(p.machine.pc(0), i);
  }
}

TEST(Machine, ThreadsRunIndependently) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  p.machine.start(0, 0);
  p.machine.start(1, 0);
  p.machine.run_slice(0, Budget::of_lines(3));
  p.machine.run_slice(1, Budget::of_lines(2));
  EXPECT_EQ(p.global("lines").i, 5);
  EXPECT_EQ(p.machine.start(7, 0), vm::RunError::NoSuchThread);
  EXPECT_EQ(p.machine.start(0, 9), vm::RunError::NoSuchRoutine);
}

TEST(Machine, StartChecksArguments) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "out" 1
.routine function "twice" in=1 out=0 entry=twice
.local int "x"
twice:
  LDL 0
  LDL 0
  ADDI
  STG out
  RET
)"));
  EXPECT_EQ(p.machine.start(0, 0), vm::RunError::BadArguments);
  const Value arg = Value::of_int(21);
  ASSERT_EQ(p.machine.start(0, 0, &arg, 1), vm::RunError::None);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
  EXPECT_EQ(p.global("out").i, 42);
}

TEST(Machine, ErrorInEventIsNotCaughtByInterruptedTry) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "caught" 1
.routine function "main" in=0 out=0 entry=main
.routine auto "bad" in=0 out=0 entry=bad
main:
  TRY handler
spin:
  YIELD
  JMP spin
handler:
  PUSHI 1
  STG caught
  RET
bad:
  PUSHI 1
  PUSHI 0
  DIVI
  POP
  RET
)"));
  p.machine.start(0, 0);
  p.machine.run_slice(0, Budget::unlimited());
  p.machine.interrupt(0, 1);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Error);
  EXPECT_EQ(p.machine.last_error(0), vm::RunError::DivisionByZero);
  EXPECT_EQ(p.global("caught").i, 0);
}

// The same program with TRYALL: its catch block runs, and the event frame is dropped.
TEST(Machine, TryAllCatchesAnEventsError) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "caught" 1
.routine function "main" in=0 out=0 entry=main
.routine auto "bad" in=0 out=0 entry=bad
main:
  TRYALL handler
spin:
  YIELD
  JMP spin
handler:
  ERRCODE
  STG caught
  RET
bad:
  PUSHI 1
  PUSHI 0
  DIVI
  POP
  RET
)"));
  p.machine.start(0, 0);
  p.machine.run_slice(0, Budget::unlimited());
  p.machine.interrupt(0, 1);
  EXPECT_EQ(p.machine.frame_count(0), 2u);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Finished);
  EXPECT_EQ(p.global("caught").i, static_cast<int32_t>(vm::RunError::DivisionByZero));
}

TEST(Machine, WideDivisionChecksItsDivisor) {
  LoadedProgram p;
  ASSERT_TRUE(
      p.load(".routine function \"main\" in=0 out=0 entry=main\nmain:\n"
             "  PUSHI 7\n  PUSHI 7\n  PUSHI 0\n  MULDIV\n  POP\n  RET\n"));
  p.machine.start(0, 0);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Error);
  EXPECT_EQ(p.machine.last_error(0), vm::RunError::DivisionByZero);
}

TEST(Machine, DataMemoryIsCheckedFromInsideAndOutside) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "a" 2
.global float "f" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI -1
  PUSHI 9
  STM
  RET
)"));
  EXPECT_EQ(p.machine.memory_words(), 3u);
  EXPECT_TRUE(p.machine.write_memory(2, Value::of_float(2.5f)));
  EXPECT_EQ(p.global("f").f, 2.5f);
  EXPECT_TRUE(p.machine.write_global(0, 1, Value::of_int(8)));
  Value v;
  ASSERT_TRUE(p.machine.read_memory(1, v));
  EXPECT_EQ(v.i, 8);
  EXPECT_FALSE(p.machine.read_memory(3, v));
  EXPECT_FALSE(p.machine.write_memory(UINT32_MAX, v));
  p.machine.start(0, 0);  // a negative address is no address
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Error);
  EXPECT_EQ(p.machine.last_error(0), vm::RunError::BadAddress);
}

TEST(Machine, DebuggerReadsLocalsAndFrames) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.routine function "main" in=0 out=0 entry=main
.local int "a"
.routine function "inner" in=1 out=0 entry=inner
.local int "x"
main:
  PUSHI 5
  STL 0
  PUSHI 9
  CALL inner 0
  RET
inner:
  YIELD
  RET
)"));
  p.machine.start(0, 0);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Yielded);
  ASSERT_EQ(p.machine.frame_count(0), 2u);
  EXPECT_EQ(p.machine.frame(0, 0).routine, 1u);
  EXPECT_EQ(p.machine.frame(0, 1).routine, 0u);
  EXPECT_EQ(p.machine.frame(0, 1).pc, 5u);  // after the CALL
  Value v;
  ASSERT_TRUE(p.machine.read_local(0, 0, 0, v));
  EXPECT_EQ(v.i, 9);
  ASSERT_TRUE(p.machine.read_local(0, 1, 0, v));
  EXPECT_EQ(v.i, 5);
  EXPECT_FALSE(p.machine.read_local(0, 0, 1, v));
}

TEST(Machine, GlobalsAreCheckedFromOutside) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCounter));
  Value v;
  EXPECT_TRUE(p.machine.write_global(0, 0, Value::of_int(5)));
  EXPECT_FALSE(p.machine.write_global(0, 1, Value::of_int(5)));
  EXPECT_FALSE(p.machine.read_global(2, 0, v));
  EXPECT_EQ(p.global("lines").i, 5);
}

}  // namespace
}  // namespace uprog::test

namespace uprog::test {
namespace {

TEST(Machine, HaltedWaitKeepsItsTime) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "done" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 10
  WAIT 1000
  PUSHI 1
  STG done
  RET
)"));
  p.machine.start(0, 0);
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Waiting);
  p.machine.halt(0);
  p.host.clock_us = 20000;
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Halted);
  p.host.clock_us = 5000;  // resumed before the wait is over: it still waits
  p.machine.resume(0);
  EXPECT_EQ(p.machine.status(0), vm::ThreadStatus::Waiting);
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Waiting);
  EXPECT_EQ(p.global("done").i, 0);
  p.host.clock_us = 10000;
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Finished);
  EXPECT_EQ(p.global("done").i, 1);
}

// threads_in() names, for each status, the threads in it: through every change of status.
void expect_masks_match(const vm::Machine& m) {
  for (uint8_t s = 0; s <= static_cast<uint8_t>(ThreadStatus::Error); ++s) {
    const auto status = static_cast<ThreadStatus>(s);
    uint32_t expected = 0;
    for (uint32_t t = 0; t < m.thread_count(); ++t)
      if (m.status(t) == status) expected |= 1u << t;
    EXPECT_EQ(m.threads_in(status), expected) << vm::thread_status_name(status);
  }
}

TEST(Machine, ThreadsInEachStatusFollowEveryChange) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "n" 1
.routine function "main" in=0 out=0 entry=main
.routine auto "on_event" in=0 out=0 entry=on_event
main:
  PUSHI 10
  WAIT 1000
  LDG n
  PUSHI 0
  DIVI
  POP
  RET
on_event:
  EOL
  RET
)"));
  vm::Machine& m = p.machine;
  expect_masks_match(m);
  EXPECT_EQ(m.threads_in(ThreadStatus::Idle), 0xFu);  // four threads, all idle
  m.start(1, 0);
  m.start(2, 0);
  EXPECT_EQ(m.threads_in(ThreadStatus::Running), 0x6u);
  EXPECT_EQ(m.run_slice(1, Budget::unlimited()).end, SliceEnd::Waiting);
  EXPECT_EQ(m.threads_in(ThreadStatus::Waiting), 0x2u);
  expect_masks_match(m);
  m.halt(1);
  EXPECT_EQ(m.threads_in(ThreadStatus::Halted), 0x2u);
  m.resume(1);  // back to its wait
  EXPECT_EQ(m.threads_in(ThreadStatus::Waiting), 0x2u);
  ASSERT_EQ(m.interrupt(1, 1), vm::RunError::None);  // the event runs, the wait held
  EXPECT_EQ(m.threads_in(ThreadStatus::Running), 0x6u);
  m.run_slice(1, Budget::of_lines(1));
  EXPECT_EQ(m.run_slice(1, Budget::of_instructions(1)).end, SliceEnd::Waiting);  // its RET
  EXPECT_EQ(m.threads_in(ThreadStatus::Waiting), 0x2u);
  expect_masks_match(m);
  ASSERT_TRUE(m.set_breakpoint(0));
  m.start(3, 0);
  EXPECT_EQ(m.run_slice(3, Budget::unlimited()).end, SliceEnd::Breakpoint);
  EXPECT_EQ(m.threads_in(ThreadStatus::AtBreakpoint), 0x8u);
  m.resume(3);
  EXPECT_EQ(m.threads_in(ThreadStatus::Running), 0xCu);
  p.host.clock_us = 20000;
  EXPECT_EQ(m.run_slice(1, Budget::unlimited()).end, SliceEnd::Error);  // 0 / 0
  EXPECT_EQ(m.threads_in(ThreadStatus::Error), 0x2u);
  expect_masks_match(m);
  m.kill(2);
  m.kill(1);
  EXPECT_EQ(m.threads_in(ThreadStatus::Idle), 0x7u);
  expect_masks_match(m);
}

// restart() is start() without inputs, for a cyclic task's next run: on an idle thread (its
// routine finished, or it was killed) the routine begins afresh, its locals at 0; a thread that
// is still running, or stopped by an error, is reset first; refusals are start()'s.
TEST(Machine, RestartBeginsTheRoutineAfreshAsStartDoes) {
  const char* text = R"(
.global int "runs" 1
.global int "seen" 1
.routine function "main" in=0 out=0 entry=main
.local int "x"
.routine function "twice" in=1 out=0 entry=twice
.local int "y"
.routine function "fail" in=0 out=0 entry=fail
main:
  LDL 0
  PUSHI 1
  ADDI
  STL 0
  LDL 0
  STG seen
  LDG runs
  PUSHI 1
  ADDI
  STG runs
  EOL
  RET
twice:
  RET
fail:
  PUSHI 1
  PUSHI 0
  DIVI
  POP
  RET
)";
  LoadedProgram p;
  ASSERT_TRUE(p.load(text));
  vm::Machine& m = p.machine;
  for (int32_t run = 1; run <= 2; ++run) {  // its local starts at 0 each time: seen stays 1
    ASSERT_EQ(m.restart(0, 0), vm::RunError::None);
    EXPECT_EQ(m.status(0), ThreadStatus::Running);
    expect_masks_match(m);
    EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
    EXPECT_EQ(m.status(0), ThreadStatus::Idle);
    EXPECT_EQ(p.global("runs").i, run);
    EXPECT_EQ(p.global("seen").i, 1);
  }
  // Stopped in the middle (LDL, PUSHI run): the next restart begins at the top, its stack empty.
  ASSERT_EQ(m.restart(0, 0), vm::RunError::None);
  EXPECT_EQ(m.run_slice(0, Budget::of_instructions(2)).end, SliceEnd::BudgetSpent);
  EXPECT_EQ(m.operand_stack(0).size(), 2u);
  ASSERT_EQ(m.restart(0, 0), vm::RunError::None);
  EXPECT_EQ(m.pc(0), 0u);
  EXPECT_EQ(m.frame_count(0), 1u);
  EXPECT_TRUE(m.operand_stack(0).empty());
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
  EXPECT_EQ(p.global("runs").i, 3);
  EXPECT_EQ(p.global("seen").i, 1);
  // Stopped by an error: restarted with no error left.
  ASSERT_EQ(m.restart(0, 2), vm::RunError::None);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Error);
  EXPECT_EQ(m.last_error(0), vm::RunError::DivisionByZero);
  ASSERT_EQ(m.restart(0, 0), vm::RunError::None);
  EXPECT_EQ(m.last_error(0), vm::RunError::None);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
  expect_masks_match(m);
  // start()'s refusals, the idle thread left as it was.
  EXPECT_EQ(m.restart(0, 1), vm::RunError::BadArguments);  // "twice" takes an input
  EXPECT_EQ(m.restart(7, 0), vm::RunError::NoSuchThread);
  EXPECT_EQ(m.restart(0, 9), vm::RunError::NoSuchRoutine);
  EXPECT_EQ(m.status(0), ThreadStatus::Idle);
  LoadedProgram small;
  vm::MachineConfig no_locals;
  no_locals.locals = 0;
  ASSERT_TRUE(small.load(text, no_locals));
  EXPECT_EQ(small.machine.restart(0, 0), vm::RunError::LocalsExhausted);  // "main" needs one
  EXPECT_EQ(small.machine.status(0), ThreadStatus::Idle);
  EXPECT_EQ(small.machine.restart(0, 2), vm::RunError::None);  // "fail" needs none
}

}  // namespace
}  // namespace uprog::test
