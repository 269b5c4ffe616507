// One test per fixed limit of the machine: each limit holds exactly, and one more fails cleanly.
#include <gtest/gtest.h>

#include <string>

#include "vm_fixture.h"

namespace uprog::test {
namespace {

using vm::RunError;
using vm::SliceEnd;

std::string pushes(int n) {
  std::string text = ".routine function \"main\" in=0 out=0 entry=main\nmain:\n";
  for (int i = 0; i < n; ++i) text += "  PUSHI 1\n";
  for (int i = 0; i < n; ++i) text += "  POP\n";
  return text + "  RET\n";
}

TEST(Limits, ExpressionStackHoldsFiftyEntries) {
  LoadedProgram ok;
  EXPECT_TRUE(ok.load(pushes(50)));
  LoadedProgram too_deep;
  EXPECT_FALSE(too_deep.load(pushes(51)));
  EXPECT_EQ(too_deep.status.verify, bytecode::VerifyError::StackOverflow);
}

// A routine that recurses `depth` times (depth = its input).
const char* kRecursion = R"(
.global int "reached" 1
.routine function "down" in=1 out=0 entry=down
.local int "n"
down:
  LDL 0
  STG reached
  LDL 0
  JZ bottom
  LDL 0
  PUSHI 1
  SUBI
  CALL down 0
bottom:
  RET
)";

TEST(Limits, CallStackHoldsThirtyFrames) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kRecursion));
  Value arg = Value::of_int(29);  // 30 frames: the start and 29 calls
  p.machine.start(0, 0, &arg, 1);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
  arg = Value::of_int(30);
  p.machine.start(0, 0, &arg, 1);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Error);
  EXPECT_EQ(p.machine.last_error(0), RunError::CallDepth);
  EXPECT_EQ(p.global("reached").i, 1);  // the 30th frame ran, the 31st was refused
}

TEST(Limits, LocalsRunOutCleanly) {
  LoadedProgram p;
  vm::MachineConfig config;
  config.locals = 10;  // room for 10 frames of one local
  ASSERT_TRUE(p.load(kRecursion, config));
  Value arg = Value::of_int(9);
  p.machine.start(0, 0, &arg, 1);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);
  arg = Value::of_int(10);
  p.machine.start(0, 0, &arg, 1);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Error);
  EXPECT_EQ(p.machine.last_error(0), RunError::LocalsExhausted);
}

std::string nested_tries(int n) {
  std::string text = ".routine function \"main\" in=0 out=0 entry=main\nmain:\n";
  for (int i = 0; i < n; ++i) text += "  TRY catch\n";
  for (int i = 0; i < n; ++i) text += "  ENDTRY\n";
  return text + "  RET\ncatch:\n  RAISE 14\n";
}

TEST(Limits, EightNestedTryBlocks) {
  LoadedProgram ok;
  ASSERT_TRUE(ok.load(nested_tries(8)));
  ok.machine.start(0, 0);
  EXPECT_EQ(ok.run_to_end().end, SliceEnd::Finished);
  LoadedProgram deep;
  ASSERT_TRUE(deep.load(nested_tries(9)));
  deep.machine.start(0, 0);
  // The ninth TRY fails; the eighth block catches that, and its catch raises again.
  EXPECT_EQ(deep.run_to_end().end, SliceEnd::Error);
  EXPECT_EQ(deep.machine.last_error(0), RunError::Raised);
}

TEST(Limits, SixteenBreakpoints) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(pushes(20)));
  for (uint32_t pc = 0; pc < 16; ++pc) EXPECT_TRUE(p.machine.set_breakpoint(pc)) << pc;
  EXPECT_FALSE(p.machine.set_breakpoint(16));
  EXPECT_TRUE(p.machine.clear_breakpoint(3));
  EXPECT_TRUE(p.machine.set_breakpoint(16));
}

TEST(Limits, FourThreads) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(pushes(1)));
  EXPECT_EQ(p.machine.thread_count(), 4u);
  EXPECT_EQ(p.machine.start(3, 0), RunError::None);
  EXPECT_EQ(p.machine.start(4, 0), RunError::NoSuchThread);
}

TEST(Limits, EventEntryNeedsAFreeFrame) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.routine function "down" in=1 out=0 entry=down
.local int "n"
.routine auto "event" in=0 out=0 entry=event
down:
  LDL 0
  JZ bottom
  LDL 0
  PUSHI 1
  SUBI
  CALL down 0
  RET
bottom:
  YIELD
  RET
event:
  RET
)"));
  Value arg = Value::of_int(29);
  p.machine.start(0, 0, &arg, 1);
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, SliceEnd::Yielded);
  EXPECT_EQ(p.machine.interrupt(0, 1), RunError::InterruptDepth);
  EXPECT_EQ(p.run_to_end().end, SliceEnd::Finished);  // the program itself goes on
}

TEST(Limits, MemoryTooSmallIsRefused) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(pushes(1)));
  vm::Machine other;
  uint64_t small[4];
  const auto status = other.load(p.bytes.data(), p.bytes.size(), {}, small, sizeof small, p.host);
  EXPECT_TRUE(status.no_memory);
  EXPECT_FALSE(other.loaded());
}

// Loops that never end a line: an endless jump, a restart and a catch before its try. The
// back-jump budget stops each slice after exactly that many iterations, and the next slice goes
// on from there.
TEST(Limits, BackJumpBudgetBoundsLoopsWithoutALineEnd) {
  const char* kLoops = R"(
.global int "n" 1
.routine function "spin" in=0 out=0 entry=spin
.routine function "restart" in=0 out=0 entry=restart
.routine function "catcher" in=0 out=0 entry=catcher
spin:
  LDG n
  PUSHI 1
  ADDI
  STG n
  JMP spin
restart:
  LDG n
  PUSHI 1
  ADDI
  STG n
  RESET 1
catcher:
  TRY catcher
  LDG n
  PUSHI 1
  ADDI
  STG n
  RAISE 5
)";
  for (uint32_t routine = 0; routine < 3; ++routine) {
    LoadedProgram p;
    ASSERT_TRUE(p.load(kLoops));
    p.machine.start(0, routine);
    vm::Budget budget;
    budget.back_jumps = 1000;
    EXPECT_EQ(p.machine.run_slice(0, budget).end, SliceEnd::BudgetSpent) << routine;
    EXPECT_EQ(p.global("n").i, 1000) << routine;
    EXPECT_EQ(p.machine.run_slice(0, budget).end, SliceEnd::BudgetSpent) << routine;
    EXPECT_EQ(p.global("n").i, 2000) << routine;
  }
}

}  // namespace
}  // namespace uprog::test
