// The loader's fused copies (line_runs.h) run a CUP program as its lines do: each program here
// runs once in slices of one line (the drive's cycle, which never takes a copy), once without a
// line budget (which does) and once in slices of 7 and of 100 lines, and ends with the same general
// data, the same end and, for an error, the same CUP line.
#include <gtest/gtest.h>

#include <array>

#include "bytecode/image_view.h"
#include "bytecode/opcodes.h"
#include "dialects/pup/cup_loader.h"
#include "vm/machine.h"

namespace uprog::pup {
namespace {

// These programs reach no keyword but AGenData, which is the image's own global.
class NoHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t, int32_t, Value&) override { return 1; }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return 1; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override { return 1; }
  vm::CommandStatus message(uint32_t, uint32_t, const Value*, uint32_t) override { return 1; }
  uint32_t now_us() override { return 0; }
};

struct Outcome {
  vm::SliceEnd end;
  uint32_t line = 0;  // where an error stopped it
  std::array<Value, kGenDataSize> gen_data{};
  uint64_t slices = 0;
};

Outcome run(const LoadedCup& cup, vm::Budget budget) {
  Outcome out;
  const std::vector<uint8_t> bytes = bytecode::encode(cup.image);
  bytecode::ImageView view;
  EXPECT_EQ(bytecode::load_image(bytes.data(), bytes.size(), view), bytecode::LoadError::Ok);
  const vm::MachineConfig config;
  std::vector<uint64_t> memory(vm::Machine::memory_needed(view, config) / 8 + 1);
  NoHost host;
  vm::Machine machine;
  EXPECT_TRUE(
      machine.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, host)
          .ok());
  EXPECT_TRUE(bind_gen_data(machine, cup, out.gen_data));
  machine.start(0, static_cast<uint32_t>(cup.task_routine[1]));
  vm::SliceResult r{};
  do {
    r = machine.run_slice(0, budget);
    ++out.slices;
  } while (r.end == vm::SliceEnd::LineEnd && out.slices < 1000000);
  out.end = r.end;
  if (r.end == vm::SliceEnd::Error) out.line = cup.line_of(machine.pc(0));
  return out;
}

LoadedCup load(std::vector<std::string> lines) {
  CupProgram p;
  p.name = "copies";
  p.lines = std::move(lines);
  std::string why;
  auto loaded = load_cup(p, &why);
  EXPECT_TRUE(loaded) << why;
  return loaded ? std::move(*loaded) : LoadedCup{};
}

size_t count_of(const LoadedCup& cup, bytecode::Op op) {
  size_t n = 0;
  const auto& code = cup.image.code;
  for (size_t pc = 0; pc < code.size(); pc += bytecode::op_length(bytecode::word_op(code[pc])))
    n += bytecode::word_op(code[pc]) == op ? 1 : 0;
  return n;
}

// Every budget gives what slices of one line give; that one took more slices than it has copies
// says the other budgets did run copies.
void expect_same_runs(const LoadedCup& cup, const Outcome& lines) {
  ASSERT_GT(count_of(cup, bytecode::Op::JLINES), 0u) << "no copy to test";
  for (const vm::Budget budget :
       {vm::Budget::unlimited(), vm::Budget::of_lines(7), vm::Budget::of_lines(100)}) {
    const Outcome other = run(cup, budget);
    EXPECT_EQ(other.end, lines.end);
    EXPECT_EQ(other.line, lines.line);
    for (size_t i = 0; i < kGenDataSize; ++i)
      EXPECT_EQ(other.gen_data[i].i, lines.gen_data[i].i) << "AGenData[" << i + 1 << "]";
  }
}

// A loop with every kind of branch, AMath's operations the VM has (a division by a constant),
// ACompare and indexed AGenData: I from 1 to 29, S the sum of those not divisible by 3, X
// the count of those above 20, and AGenData[100 + I] = (I / 7) xor (I && 1).
const std::vector<std::string> kLoop = {
    "AProgTask[1]",                    //  1
    "AGenData[1]=1",                   //  2 I = 1
    "APushParam,AGenData[1]",          //  3 loop: I >= 30 ends it
    "APushConstant,30",                //  4
    "AJump[6],37",                     //  5
    "APushParam,AGenData[1]",          //  6 I % 3 == 0 skips the sum
    "APushConstant,3",                 //  7
    "AMath[5]",                        //  8
    "AJump[9],14",                     //  9
    "APushParam,AGenData[2]",          // 10 S = S + I
    "APushParam,AGenData[1]",          // 11
    "AMath[1]",                        // 12
    "APopParam,AGenData[2]",           // 13
    "APushParam,AGenData[1]",          // 14 (I / 7) xor (I && 1) into AGenData[100 + I]
    "APushConstant,7",                 // 15
    "AMath[4]",                        // 16
    "APushParam,AGenData[1]",          // 17
    "APushConstant,1",                 // 18
    "AMath[20]",                       // 19
    "AMath[12]",                       // 20
    "APushParam,AGenData[1]",          // 21
    "APopParamIdx[40],AGenData[101]",  // 22
    "APushParam,AGenData[1]",          // 23 I > 20 counts in X (ACompare[5], then AJump[10])
    "APushConstant,20",                // 24
    "ACompare[5]",                     // 25
    "AJump[9],31",                     // 26
    "APushParam,AGenData[3]",          // 27
    "APushConstant,1",                 // 28
    "AMath[1]",                        // 29
    "APopParam,AGenData[3]",           // 30
    "APushParam,AGenData[1]",          // 31 I = I + 1
    "APushConstant,1",                 // 32
    "AMath[1]",                        // 33
    "APopParam,AGenData[1]",           // 34
    "APushConstant,1",                 // 35 AJump[2]: the top above 0, as it is
    "AJump[2],3",                      // 36
    "APushParam,AGenData[2]",          // 37 done: AGenData[4] = S
    "APopParam,AGenData[4]",           // 38
};

TEST(CupCopies, ALoopRunsAsItsLines) {
  const LoadedCup cup = load(kLoop);
  const Outcome lines = run(cup, vm::Budget::of_lines(1));
  ASSERT_EQ(lines.end, vm::SliceEnd::Finished);
  EXPECT_EQ(lines.gen_data[0].i, 30);         // I
  EXPECT_EQ(lines.gen_data[1].i, 435 - 135);  // 1..29 less 3, 6, ..., 27
  EXPECT_EQ(lines.gen_data[2].i, 9);          // 21..29
  EXPECT_EQ(lines.gen_data[3].i, 300);
  EXPECT_EQ(lines.gen_data[100].i, (1 / 7) ^ 1);   // AGenData[101], I = 1
  EXPECT_EQ(lines.gen_data[113].i, (14 / 7) ^ 1);  // AGenData[114], I = 14
  expect_same_runs(cup, lines);
  EXPECT_LT(run(cup, vm::Budget::unlimited()).slices, lines.slices);
}

// A loop whose copy goes on into its next turns, left at each of them: K counts to N, S sums
// the odd K (a turn of 16 lines, four in a path of 64 lines, its test and an `if` its two
// branches) or every K (without the `if`: 12 lines, five turns).
TEST(CupCopies, ALoopsCopyTakesSeveralTurnsAndLeavesAtAnyOfThem) {
  for (const bool odd_only : {true, false}) {
    for (int32_t n = 0; n <= 12; ++n) {
      std::vector<std::string> lines = {
          "AProgTask[1]",                      //  1
          "AGenData[9]=" + std::to_string(n),  //  2 N
          "APushParam,AGenData[1]",            //  3 loop: K >= N ends it
          "APushParam,AGenData[9]",            //  4
          "AJump[6],19",                       //  5
          "APushParam,AGenData[1]",            //  6 an even K skips the sum
          "APushConstant,2",                   //  7
          "AMath[5]",                          //  8
          "AJump[9],14",                       //  9
          "APushParam,AGenData[2]",            // 10 S = S + K
          "APushParam,AGenData[1]",            // 11
          "AMath[1]",                          // 12
          "APopParam,AGenData[2]",             // 13
          "APushParam,AGenData[1]",            // 14 K = K + 1
          "APushConstant,1",                   // 15
          "AMath[1]",                          // 16
          "APopParam,AGenData[1]",             // 17
          "AJump[1],3",                        // 18
          "APushParam,AGenData[2]",            // 19 done: AGenData[3] = S
          "APopParam,AGenData[3]",             // 20
      };
      if (!odd_only) {  // without lines 6 to 9, the jumps' lines 4 less
        lines.erase(lines.begin() + 5, lines.begin() + 9);
        lines[4] = "AJump[6],15";
        lines[13] = "AJump[1],3";
      }
      const LoadedCup cup = load(lines);
      const Outcome by_line = run(cup, vm::Budget::of_lines(1));
      ASSERT_EQ(by_line.end, vm::SliceEnd::Finished);
      EXPECT_EQ(by_line.gen_data[0].i, n);
      EXPECT_EQ(by_line.gen_data[2].i, odd_only ? (n / 2) * (n / 2) : n * (n - 1) / 2);
      expect_same_runs(cup, by_line);
    }
  }
}

// An accumulation of an expression, S = S + I % 3 * 2 for I from 1 to 10 (AMath[5] %, [2] *,
// [1] +): the copies end as the lines do, S = 2 * (1 + 2 + 0 + ... + 1) = 20.
TEST(CupCopies, AnAccumulationOfAnExpressionRunsAsItsLines) {
  const LoadedCup cup = load({
      "AProgTask[1]",            //  1
      "AGenData[1]=1",           //  2 I = 1
      "APushParam,AGenData[1]",  //  3 loop: I >= 11 ends it
      "APushConstant,11",        //  4
      "AJump[6],19",             //  5
      "APushParam,AGenData[2]",  //  6 S = S + I % 3 * 2
      "APushParam,AGenData[1]",  //  7
      "APushConstant,3",         //  8
      "AMath[5]",                //  9
      "APushConstant,2",         // 10
      "AMath[2]",                // 11
      "AMath[1]",                // 12
      "APopParam,AGenData[2]",   // 13
      "APushParam,AGenData[1]",  // 14 I = I + 1
      "APushConstant,1",         // 15
      "AMath[1]",                // 16
      "APopParam,AGenData[1]",   // 17
      "AJump[1],3",              // 18
      "APushParam,AGenData[2]",  // 19 done: AGenData[3] = S
      "APopParam,AGenData[3]",   // 20
  });
  const Outcome lines = run(cup, vm::Budget::of_lines(1));
  ASSERT_EQ(lines.end, vm::SliceEnd::Finished);
  EXPECT_EQ(lines.gen_data[0].i, 11);
  EXPECT_EQ(lines.gen_data[1].i, 20);
  EXPECT_EQ(lines.gen_data[2].i, 20);
  expect_same_runs(cup, lines);
}

// An index out of its window inside a copy (I reaches 4, the window has 3 places): error 4 at
// line 8 however the program runs, the stores before it made.
TEST(CupCopies, AnErrorInACopyNamesItsLine) {
  const LoadedCup cup = load({
      "AProgTask[1]",                  // 1
      "APushParam,AGenData[1]",        // 2 loop: I = I + 1
      "APushConstant,1",               // 3
      "AMath[1]",                      // 4
      "APopParam,AGenData[1]",         // 5
      "APushParam,AGenData[1]",        // 6 AGenData[10 + I - 1] = I
      "APushParam,AGenData[1]",        // 7
      "APopParamIdx[3],AGenData[10]",  // 8
      "AJump[1],2",                    // 9
  });
  const Outcome lines = run(cup, vm::Budget::of_lines(1));
  ASSERT_EQ(lines.end, vm::SliceEnd::Error);
  EXPECT_EQ(lines.line, 8u);
  EXPECT_EQ(lines.gen_data[0].i, 4);
  EXPECT_EQ(lines.gen_data[11].i, 3);
  expect_same_runs(cup, lines);
}

// A program whose every other line is a jump target starts a copy there, each copying what
// follows: all copies together stay within 4096 code words and 4 a line.
TEST(CupCopies, CopiesStayWithinTheirShare) {
  std::vector<std::string> lines = {"AProgTask[1]"};
  constexpr uint32_t kPairs = 2000;
  for (uint32_t i = 0; i < kPairs; ++i) {
    lines.push_back("APushParam,AGenData[1]");
    lines.push_back("AJump[9]," + std::to_string(lines.size() + 2));
  }
  const LoadedCup cup = load(lines);
  const size_t copies = cup.image.code.size() - cup.line_pc.back() - 1;  // past the EXIT
  EXPECT_GT(count_of(cup, bytecode::Op::JLINES), 100u);
  EXPECT_LE(copies, 4096u + 4u * lines.size());
  EXPECT_EQ(run(cup, vm::Budget::unlimited()).end, vm::SliceEnd::Finished);
}

}  // namespace
}  // namespace uprog::pup
