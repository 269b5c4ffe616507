// Fusion at load (vm/quicken.cpp, vm/fused.def): the first word of a matching base sequence gets
// the fused opcode and nothing else changes; never across a place control can enter or inside a
// line; a breakpoint inside a fused sequence is hit; a slice that counts instructions counts
// base ones; and the VM cases together form every fused instruction (and the case runner runs
// them, so each handler is checked against the expectations its base code has).
#include "vm/quicken.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "bytecode/image_view.h"
#include "testlib/test_files.h"
#include "vm/fused.h"
#include "vm_fixture.h"

namespace uprog::test {
namespace {

using bytecode::Op;

struct Quickened {
  std::vector<uint32_t> base;
  std::vector<uint32_t> code;
  uint32_t formed = 0;
};

// The code of `text` assembled, and the same code quickened as Machine::load does it.
Quickened quickened(const std::string& text) {
  LoadedProgram p;
  EXPECT_TRUE(p.load(text));
  Quickened q;
  q.base = p.image.code;
  q.code = p.image.code;
  bytecode::ImageView view;
  EXPECT_EQ(bytecode::load_image(p.bytes.data(), p.bytes.size(), view), bytecode::LoadError::Ok);
  std::vector<uint32_t> scratch(vm::quicken_scratch_words(static_cast<uint32_t>(q.code.size())));
  q.formed = vm::quicken(q.code.data(), static_cast<uint32_t>(q.code.size()), view, scratch.data());
  return q;
}

uint32_t opcode(vm::Fused f) { return vm::fused_number(f); }

// The quickened code as the execute loop dispatches it, one line an instruction: its pc and
// its name, a fused one's name where it was formed, a base one's elsewhere.
std::vector<std::string> dispatched(const Quickened& q) {
  std::vector<std::string> lines;
  for (uint32_t pc = 0; pc < q.code.size(); pc += vm::instruction_length(q.code[pc])) {
    const std::string name = vm::is_fused(q.code[pc])
                                 ? vm::kFusedNames[vm::fused_of(q.code[pc])]
                                 : bytecode::op_name(bytecode::word_op(q.code[pc]));
    lines.push_back(std::to_string(pc) + " " + name);
  }
  return lines;
}

TEST(Quicken, OnlyTheFirstWordOfTheSequenceChanges) {
  const Quickened q = quickened(R"(
.global int "g" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG g
  PUSHI 3
  JLTI out
  PUSHI 1
  STG g
out:
  RET
)");
  ASSERT_EQ(q.formed, 2u);
  EXPECT_EQ(q.code[0] & 0xFFu, opcode(vm::Fused::JLTGK));
  EXPECT_EQ(vm::base_word(q.code[0]), q.base[0]);
  EXPECT_EQ(q.code[1], q.base[1]);  // the immediate stays where it was, and the target
  EXPECT_EQ(q.code[2], q.base[2]);
  EXPECT_EQ(vm::instruction_length(q.code[0]), 3u);
  EXPECT_EQ(q.code[3] & 0xFFu, opcode(vm::Fused::STGI));
  EXPECT_EQ(q.code[5], q.base[5]);
}

TEST(Quicken, NeverAcrossAPlaceControlCanEnter) {
  const Quickened q = quickened(R"(
.global int "g" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG g
again:
  PUSHI 3
  JLTI out
  PUSHI 1
  STG g
  PUSHI 0
  JMP again
out:
  RET
)");
  // `again` is a jump target: LDG g stays alone, PUSHI 3; JLTI has no fused form, PUSHI 1;
  // STG g is STGI.
  EXPECT_EQ(q.code[0], q.base[0]);
  EXPECT_EQ(q.code[1], q.base[1]);
  EXPECT_EQ(q.code[3] & 0xFFu, opcode(vm::Fused::STGI));
  EXPECT_EQ(q.formed, 1u);
}

TEST(Quicken, NeverInsideALineAndTheLastWordsMarkMoves) {
  const Quickened q = quickened(R"(
.global int "a" 1
.global int "b" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG.eol a
  STG b
  LDG a
  STG.eol b
  RET
)");
  // A line ends after the first LDG: its STG is no part of a fused MOVG. The second pair is,
  // and the fused word carries the mark its STG did (the line ends where it did).
  EXPECT_EQ(q.code[0], q.base[0]);
  EXPECT_EQ(q.code[2] & 0xFFu, opcode(vm::Fused::MOVG));
  EXPECT_TRUE(bytecode::word_ends_line(q.code[2]));
  EXPECT_FALSE(bytecode::word_ends_line(q.base[2]));
  EXPECT_EQ(vm::base_word(q.code[2]), q.base[2]);
}

TEST(Quicken, APatternsConditionHolds) {
  const Quickened q = quickened(R"(
.global int "a" 1
.global int "b" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG a
  PUSHI 1
  ADDI
  STG b
  LDG a
  PUSHI 1
  ADDI
  STG a
  RET
)");
  // a + 1 into b is no INCG (the globals differ) but the assignment ADDGKS; into a it is.
  EXPECT_EQ(q.code[0] & 0xFFu, opcode(vm::Fused::ADDGKS));
  EXPECT_EQ(q.code[3], q.base[3]);
  EXPECT_EQ(q.code[4] & 0xFFu, opcode(vm::Fused::INCG));
}

TEST(Quicken, AnAssignmentOfOneOperatorWithAnImmediateIsOneInstruction) {
  const Quickened q = quickened(R"(
.global int "i" 1
.global int "r" 1
.routine function "main" in=0 out=0 entry=main
.local int "a"
.local int "b"
main:
  LDG i
  PUSHI 3
  REMI
  STG r
  LDG i
  PUSHI 1
  ADDI
  STG i
  LDG i
  PUSHI 0
  DIVI
  STG r
  LDL 0
  PUSHI 7
  DIVI
  STL 1
  LDL 0
  PUSHI 0
  REMI
  STL 0
  LDG i
  PUSHI -2
  ADDI
  STL 0
  RET
)");
  // r = i % 3 is REMGKS; i = i + 1 stays INCG (the earlier of two patterns as long); i / 0
  // is no DIVGKS (the base DIVI raises the error), nor a % 0 anything; b = a / 7 is DIVLKS;
  // a global's difference stored to a local (`i - 2`, which the compile-time pass writes as
  // `+ -2`) is ADDGK, pushed, and a base STL.
  EXPECT_EQ(dispatched(q),
            (std::vector<std::string>{"0 REMGKS", "4 INCG", "8 LDG", "9 PUSHI", "10 DIVI", "11 STG",
                                      "12 DIVLKS", "16 LDL", "17 PUSHI", "18 REMI", "19 STL",
                                      "20 ADDGK", "23 STL", "24 RET"}));
  EXPECT_EQ(q.formed, 4u);
}

TEST(Quicken, AGlobalLessAnImmediateIsPushedAsOne) {
  const Quickened q = quickened(R"(
.global int "i" 1
.global int "a" 8
.routine function "main" in=0 out=0 entry=main
main:
  LDG i
  PUSHI -1
  ADDI
  PUSHI 7919
  MULI
  PUSHI 7
  STGX a
  RET
)");
  // PUP's 1-based index made 0-based (`(I - 1) * 7919`, which the compile-time pass writes as
  // `+ -1`): ADDGK, then MULIK.
  EXPECT_EQ(dispatched(q),
            (std::vector<std::string>{"0 ADDGK", "3 MULIK", "5 PUSHI", "6 STGX", "7 RET"}));
}

// A CUP loop's copy whose path ends in the loop's step, the step's line counted by the JMPLN
// (dialects/pup/line_runs.cpp): the step and the way out are one instruction, INCGJLN, and the
// lines are counted as when the store's mark counts one (tests/vm/machine_test.cpp's kLineRun,
// whose copy this is with the mark moved into the JMPLN's count).
TEST(Quicken, ACopiedLoopsStepAndItsWayOutAreOneInstruction) {
  const char* text = R"(
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
  STG a
  JMPLN next 4
)";
  const Quickened q = quickened(text);
  EXPECT_EQ(dispatched(q), (std::vector<std::string>{"0 JLINES", "2 LDG", "3 PUSHI", "4 ADDI",
                                                     "5 STG", "6 JMP", "7 INCG", "11 INCGJLN"}));
  LoadedProgram p;
  ASSERT_TRUE(p.load(text));
  p.machine.start(0, 0);
  // Ten lines: two loops of five (the run's four and the JMP's), both through the fused copy.
  const vm::SliceResult r = p.machine.run_slice(0, vm::Budget::of_lines(10));
  EXPECT_EQ(r.end, vm::SliceEnd::LineEnd);
  EXPECT_EQ(r.lines, 10u);
  EXPECT_EQ(p.global("a").i, 2);
  EXPECT_EQ(p.global("fast").i, 2);
  EXPECT_EQ(p.machine.pc(0), 0u);
}

// A family declared FUSED_PER_RELATION has an opcode for each relation, and each site gets the
// one of its compare-and-jump; a family that keeps the switch has one for all six.
TEST(Quicken, AFamilysSiteGetsTheOpcodeOfItsRelationWhereEachHasAHandler) {
  const Quickened q = quickened(R"(
.global int "g" 1
.global int "h" 1
.global float "x" 1
.global float "y" 1
.const int 30000000
.const float 1.5
.routine function "main" in=0 out=0 entry=main
.local float "f"
main:
  LDG g
  LDG h
  JLTI done
  LDG g
  LDG h
  JGEI done
  LDL 0
  PUSHK 1
  JNLTF done
  LDL 0
  PUSHK 1
  JNGEF done
  LDG x
  LDG y
  JNLTF done
  LDG x
  LDG y
  JNGEF done
  LDG g
  PUSHK 0
  JLTI done
  LDG g
  PUSHK 0
  JGEI done
done:
  RET
)");
  EXPECT_EQ(dispatched(q), (std::vector<std::string>{"0 JRELGG", "3 JRELGG", "6 JNRELFLK",
                                                     "9 JNRELFLK", "12 JNRELFGG", "15 JNRELFGG",
                                                     "18 JRELGC", "21 JRELGC", "24 RET"}));
  EXPECT_EQ(q.code[0] & 0xFFu, vm::fused_number(vm::Fused::JRELGG, 2));    // <
  EXPECT_EQ(q.code[3] & 0xFFu, vm::fused_number(vm::Fused::JRELGG, 5));    // >=
  EXPECT_EQ(q.code[6] & 0xFFu, vm::fused_number(vm::Fused::JNRELFLK, 2));  // unless <
  EXPECT_EQ(q.code[9] & 0xFFu, vm::fused_number(vm::Fused::JNRELFLK, 5));  // unless >=
  // A family that switches on its relation: one opcode for every site.
  EXPECT_EQ(q.code[12] & 0xFFu, vm::fused_number(vm::Fused::JNRELFGG));
  EXPECT_EQ(q.code[15] & 0xFFu, vm::fused_number(vm::Fused::JNRELFGG));
  EXPECT_EQ(q.code[18] & 0xFFu, vm::fused_number(vm::Fused::JRELGC));
  EXPECT_EQ(q.code[21] & 0xFFu, vm::fused_number(vm::Fused::JRELGC));
  EXPECT_EQ(vm::base_word(q.code[3]), q.base[3]);
  EXPECT_EQ(vm::instruction_length(q.code[3]), 3u);
  EXPECT_EQ(vm::base_word(q.code[9]), q.base[9]);
}

const char* kCountUp = R"(
.global int "n" 1
.routine function "main" in=0 out=0 entry=main
main:
top:
  LDG n
  PUSHI 5
  JGEI done
  LDG n
  PUSHI 1
  ADDI
  STG n
  JMP top
done:
  RET
)";

TEST(Quicken, ABreakpointInsideAFusedInstructionIsHit) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCountUp));
  ASSERT_TRUE(p.machine.set_breakpoint(2));  // the JGEI of the fused JGEGK at 0
  ASSERT_TRUE(p.machine.set_breakpoint(4));  // the PUSHI 1 of the fused INCG at 3
  p.machine.start(0, 0);
  for (int n = 0; n < 5; ++n) {
    EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Breakpoint);
    EXPECT_EQ(p.machine.pc(0), 2u) << n;
    p.machine.resume(0);
    EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Breakpoint);
    EXPECT_EQ(p.machine.pc(0), 4u) << n;
    p.machine.resume(0);
  }
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Breakpoint);
  p.machine.resume(0);
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Finished);
  EXPECT_EQ(p.global("n").i, 5);
}

TEST(Quicken, ASliceThatCountsInstructionsCountsBaseOnes) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kCountUp));
  p.machine.start(0, 0);
  // Five turns of eight base instructions, the last test (3) and RET: 44.
  const vm::SliceResult r = p.machine.run_slice(0, vm::Budget::of_instructions(1000));
  EXPECT_EQ(r.end, vm::SliceEnd::Finished);
  EXPECT_EQ(r.executed, 44u);
  EXPECT_EQ(p.global("n").i, 5);
  // And one at a time, every base instruction's place is a stop.
  LoadedProgram q;
  ASSERT_TRUE(q.load(kCountUp));
  q.machine.start(0, 0);
  std::vector<uint32_t> pcs;
  for (int i = 0; i < 8; ++i) {
    q.machine.run_slice(0, vm::Budget::of_instructions(1));
    pcs.push_back(q.machine.pc(0));
  }
  EXPECT_EQ(pcs, (std::vector<uint32_t>{1, 2, 3, 4, 5, 6, 7, 0}));
}

// The VM cases together form every fused instruction of fused.def, a folded family for each of
// its relations: each is then run by the case runner, which checks what its base code must do.
TEST(Quicken, TheCasesTogetherFormEveryFusedInstruction) {
  std::set<uint32_t> formed;
  for (const auto& f : source_files("tests/vm/cases", ".s")) {
    const Quickened q = quickened(read_whole(f));
    for (uint32_t pc = 0; pc < q.code.size(); pc += vm::instruction_length(q.code[pc]))
      if (vm::is_fused(q.code[pc])) formed.insert(q.code[pc] & 0xFFu);
  }
  // Every opcode: a folded family's six handlers each run in some case.
  for (uint32_t op = vm::kFirstFused; op < vm::kFirstFused + vm::kFusedOpcodeCount; ++op)
    EXPECT_TRUE(formed.count(op)) << "no case in tests/vm/cases forms "
                                  << vm::kFusedNames[vm::fused_of(op)] << ", relation "
                                  << op -
                                         vm::fused_number(static_cast<vm::Fused>(vm::fused_of(op)));
}

}  // namespace
}  // namespace uprog::test
