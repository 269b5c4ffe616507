// The peephole pass changes no behaviour: every VM case runs to the same end with the same
// globals before and after it. And it fuses what it should, and nothing control can enter.
#include "bytecode/peephole.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "bytecode/opcodes.h"
#include "testlib/test_files.h"
#include "vm_fixture.h"

namespace uprog::test {
namespace {

namespace fs = std::filesystem;
using bytecode::Op;

std::string read(const fs::path& p) { return read_whole(p); }

std::vector<Op> ops_of(const bytecode::Image& image) {
  std::vector<Op> ops;
  for (uint32_t pc = 0; pc < image.code.size();
       pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
    ops.push_back(bytecode::word_op(image.code[pc]));
  return ops;
}

// The instructions that carry the line-end mark, in order.
std::vector<Op> marked_ops(const bytecode::Image& image) {
  std::vector<Op> ops;
  for (uint32_t pc = 0; pc < image.code.size();
       pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
    if (bytecode::word_ends_line(image.code[pc])) ops.push_back(bytecode::word_op(image.code[pc]));
  return ops;
}

// The image of `text` after the peephole pass.
bytecode::Image optimized(const std::string& text) {
  LoadedProgram p;
  EXPECT_TRUE(p.load(text));
  bytecode::Image image = p.image;
  bytecode::optimize(image);
  return image;
}

// Runs `image` from routine 0 to its end and returns its int global `name`.
int32_t run_and_read(const bytecode::Image& image, const std::string& name) {
  LoadedProgram loaded;
  EXPECT_TRUE(loaded.load(bytecode::disassemble(image)));
  loaded.machine.start(0, 0);
  loaded.run_to_end();
  return loaded.global(name, 0).i;
}

// Loads `text` twice, the second time optimized, runs both and compares every global.
void expect_same_behaviour(const std::string& text, const std::string& name) {
  LoadedProgram plain;
  ASSERT_TRUE(plain.load(text)) << name;
  bytecode::Image image = plain.image;
  bytecode::optimize(image);
  LoadedProgram fused;
  ASSERT_TRUE(fused.load(bytecode::disassemble(image))) << name << "\n"
                                                        << bytecode::disassemble(image);
  const int main_routine = image.find_routine("main");
  ASSERT_GE(main_routine, 0);
  plain.machine.start(0, static_cast<uint32_t>(main_routine));
  fused.machine.start(0, static_cast<uint32_t>(main_routine));
  const auto a = plain.run_to_end();
  const auto b = fused.run_to_end();
  EXPECT_EQ(a.end, b.end) << name;
  EXPECT_EQ(plain.machine.last_error(0), fused.machine.last_error(0)) << name;
  EXPECT_EQ(plain.host.clock_us, fused.host.clock_us) << name;
  for (const auto& g : plain.image.globals) {
    for (uint32_t k = 0; k < g.length; ++k) {
      EXPECT_EQ(plain.global(g.name, k).bits, fused.global(g.name, k).bits)
          << name << " " << g.name;
    }
  }
}

// The code lines of `image`'s disassembly (labels and instructions, without comments).
std::vector<std::string> code_lines(const bytecode::Image& image) {
  std::istringstream in(bytecode::disassemble(image));
  std::vector<std::string> lines;
  bool in_code = false;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) {
      in_code = true;
      continue;
    }
    if (!in_code || line.rfind(".line", 0) == 0) continue;
    if (const size_t comment = line.find("  ;"); comment != std::string::npos) line.erase(comment);
    if (line.rfind("  ", 0) == 0) line.erase(0, 2);
    lines.push_back(line);
  }
  return lines;
}

// One step of a fusion's listing: the lines the pass makes of the base lines before them.
struct Rewrite {
  std::vector<std::string> fused;
  std::vector<std::string> base;
};

// Compares the listing of `text` before and after the peephole pass line by line: the base
// code is the rewrites' base lines in order, the fused code their fused lines, and the first
// line that differs is named with the rewrite it belongs to. Then the fused code must behave
// as the base code does. Returns the fused image.
bytecode::Image expect_listing(const std::string& text, const std::vector<Rewrite>& rewrites) {
  LoadedProgram plain;
  EXPECT_TRUE(plain.load(text));
  bytecode::Image image = plain.image;
  bytecode::optimize(image);
  const std::vector<std::string> base = code_lines(plain.image);
  const std::vector<std::string> fused = code_lines(image);
  size_t at_base = 0;
  size_t at_fused = 0;
  for (size_t r = 0; r < rewrites.size(); ++r) {
    const auto where = [&](const char* side, size_t line) {
      return "rewrite " + std::to_string(r) + ", " + side + " line " + std::to_string(line + 1);
    };
    for (const std::string& want : rewrites[r].base) {
      EXPECT_EQ(at_base < base.size() ? base[at_base] : "<end>", want) << where("base", at_base);
      ++at_base;
    }
    for (const std::string& want : rewrites[r].fused) {
      EXPECT_EQ(at_fused < fused.size() ? fused[at_fused] : "<end>", want)
          << where("fused", at_fused) << "\n"
          << bytecode::disassemble(image);
      ++at_fused;
    }
  }
  EXPECT_EQ(at_base, base.size()) << "base lines no rewrite names";
  EXPECT_EQ(at_fused, fused.size()) << "fused lines no rewrite names";
  expect_same_behaviour(text, "listing");
  return image;
}

std::string with_b(const std::string& instruction, uint32_t b) {
  return instruction + " " + std::to_string(b);
}

TEST(Peephole, EveryCaseBehavesTheSame) {
  for (const auto& e : fs::directory_iterator(fs::path(UPROG_SOURCE_DIR) / "tests/vm/cases"))
    expect_same_behaviour(read(e.path()), e.path().stem().string());
}

const char* kLoop = R"(
.global int "total" 1
.global float "x" 1
.const float 2.5
.routine function "main" in=0 out=0 entry=main
.local int "i"
.local int "n"
main:
  PUSHI 1
  STL 0
  PUSHI 100
  STL 1
  EOL
top:
  LDL 0
  LDL 1
  LEI
  JZ done
  LDL 0
  PUSHI 3
  REMI
  PUSHI 0
  NEI
  JZ next
  LDG total
  LDL 0
  PUSHI 7
  REMI
  ADDI
  STG total
  EOL
next:
  LDL 0
  PUSHI -1
  SUBI
  STL 0
  LDL 0
  PUSHI 50
  GTI
  JNZ skip
  LDG x
  PUSHK 0
  LTF
  JZ skip
  LDG x
  PUSHK 0
  ADDF
  STG x
skip:
  EOL
  JMP top
done:
  RET
)";

TEST(Peephole, FusesTheLoop) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kLoop));
  bytecode::Image image = p.image;
  const auto stats = bytecode::optimize(image);
  EXPECT_GT(stats.fused, 0u);
  EXPECT_LT(stats.words_after, stats.words_before);
  // The same line by line: top moves from 5 to 4, next from 22 to 12, skip from 38 to 22, done
  // from 40 to 23.
  // Each rewrite beside the base lines it replaces, as a table.
  // clang-format off
  expect_listing(kLoop, {
      {{"L0:", "PUSHI 1", "STL 0", "PUSHI 100", "STL.eol 1"},
       {"L0:", "PUSHI 1", "STL 0", "PUSHI 100", "STL 1", "EOL"}},
      {{"L4:", with_b("JGTLL L23", bytecode::pack_locals(0, 1))},
       {"L5:", "LDL 0", "LDL 1", "LEI", "JZ L40"}},
      {{"REMLK 0 3", "JZ L12"}, {"LDL 0", "PUSHI 3", "REMI", "PUSHI 0", "NEI", "JZ L22"}},
      {{"REMLK 0 7", "ADDIGEOL 0"}, {"LDG 0", "LDL 0", "PUSHI 7", "REMI", "ADDI", "STG 0", "EOL"}},
      {{"L12:", "ADDLK 0 1", "STL 0"}, {"L22:", "LDL 0", "PUSHI -1", "SUBI", "STL 0"}},
      {{with_b("JGTLK L22", bytecode::pack_local_imm(0, 50))},
       {"LDL 0", "PUSHI 50", "GTI", "JNZ L38"}},
      {{with_b("JNLTFGK L22", bytecode::pack_locals(1, 0))},
       {"LDG 1", "PUSHK 0", "LTF", "JZ L38"}},
      {{with_b("ADDFGK", bytecode::pack_locals(1, 0)), "STG 1"},
       {"LDG 1", "PUSHK 0", "ADDF", "STG 1"}},
      {{"L22:", "JMPEOL L4"}, {"L38:", "EOL", "JMP L5"}},
      {{"L23:", "RET"}, {"L40:", "RET"}},
  });
  // clang-format on
  const std::vector<Op> expected = {
      Op::PUSHI,   Op::STL,      Op::PUSHI, Op::STL,  // the EOL after the STL is its line-end mark
      Op::JGTLL,                                      // LDL i; LDL n; LEI; JZ done
      Op::REMLK,   Op::JZ,        // LDL i; PUSHI 3; REMI — then PUSHI 0; NEI; JZ
      Op::REMLK,   Op::ADDIGEOL,  // LDG total; ...; ADDI; STG total; EOL
      Op::ADDLK,   Op::STL,       // next: is a target, so the EOL before it stays
      Op::JGTLK,                  // LDL i; PUSHI 50; GTI; JNZ skip
      Op::JNLTFGK,                // LDG x; PUSHK 0; LTF; JZ skip
      Op::ADDFGK,  Op::STG,       // LDG x; PUSHK 0; ADDF
      Op::JMPEOL,                 // skip: EOL; JMP top
      Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  // STG x; skip: EOL — the EOL is a jump target, so it stays an instruction.
  EXPECT_EQ(marked_ops(image), std::vector<Op>{Op::STL}) << bytecode::disassemble(image);
  expect_same_behaviour(kLoop, "loop");
}

// `a[i] = ((i - 1) * 7919 + r) % 960` over globals: the product, the sum and the remainder
// each one instruction, with the same value.
constexpr const char* kStackImmediates = R"(
.global int "i" 1
.global int "r" 1
.global int "v" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 7
  STG i
  PUSHI 3
  STG r
  LDG i
  PUSHI 1
  SUBI
  PUSHI 7919
  MULI
  LDG r
  ADDI
  PUSHI 960
  REMI
  STG v
  RET
)";

TEST(Peephole, FusesTheStacksIntWithAnImmediateOrAGlobal) {
  // A constant's store takes the constant's index; the pass adds 7 and 3 as k0 and k1.
  // Each rewrite beside the base lines it replaces, as a table.
  // clang-format off
  const bytecode::Image image = expect_listing(kStackImmediates, {
      {{"L0:"}, {"L0:"}},
      {{"STGK 0 0"}, {"PUSHI 7", "STG 0"}},
      {{"STGK 1 1"}, {"PUSHI 3", "STG 1"}},
      {{"ADDGK 0 -1"}, {"LDG 0", "PUSHI 1", "SUBI"}},
      {{"MULIK 7919"}, {"PUSHI 7919", "MULI"}},
      {{"ADDIG 1"}, {"LDG 1", "ADDI"}},
      {{"REMIK 960"}, {"PUSHI 960", "REMI"}},
      {{"STG 2"}, {"STG 2"}},
      {{"RET"}, {"RET"}},
  });
  // clang-format on
  ASSERT_EQ(image.constants.size(), 2u);
  EXPECT_EQ(static_cast<int32_t>(image.constants[0].bits), 7);
  EXPECT_EQ(static_cast<int32_t>(image.constants[1].bits), 3);
  EXPECT_EQ(run_and_read(image, "v"), (6 * 7919 + 3) % 960);
}

// Two int globals compared, as a condition (JZ: the comparison negated) and as a fused jump.
constexpr const char* kIntGlobalCompares = R"(
.global int "v" 1
.global int "lo" 1
.global int "hits" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 4
  STG v
  PUSHI 9
  STG lo
  LDG v
  LDG lo
  LTI
  JZ skip
  INCG hits 1
skip:
  LDG lo
  LDG v
  JGEI done
  INCG hits 10
done:
  RET
)";

TEST(Peephole, FusesTwoIntGlobalsCompared) {
  constexpr uint32_t kGreaterOrEqual = 5;  // == != < <= > >=
  // "LTI; JZ" jumps when v >= lo; the code words move: skip from 10 to 8, done from 15 to 12.
  // Each rewrite beside the base lines it replaces, as a table.
  // clang-format off
  const bytecode::Image image = expect_listing(kIntGlobalCompares, {
      {{"L0:"}, {"L0:"}},
      {{"STGK 0 0"}, {"PUSHI 4", "STG 0"}},
      {{"STGK 1 1"}, {"PUSHI 9", "STG 1"}},
      {{with_b("JCMPGG L8", bytecode::pack_globals_test(0, 1, kGreaterOrEqual))},
       {"LDG 0", "LDG 1", "LTI", "JZ L10"}},
      {{"INCG 2 1"}, {"INCG 2 1"}},
      {{"L8:"}, {"L10:"}},
      {{with_b("JCMPGG L12", bytecode::pack_globals_test(1, 0, kGreaterOrEqual))},
       {"LDG 1", "LDG 0", "JGEI L15"}},
      {{"INCG 2 10"}, {"INCG 2 10"}},
      {{"L12:", "RET"}, {"L15:", "RET"}},
  });
  // clang-format on
  EXPECT_EQ(run_and_read(image, "hits"), 1);  // 4 < 9 holds; 9 >= 4 jumps over the 10
}

// A loop's step on the way out of fused code: the increment that ends its line and the JMPLN
// after it, which then counts that line end too.
TEST(Peephole, FusesTheLoopStepOutOfFusedCode) {
  const bytecode::Image image = optimized(R"(
.global int "i" 1
.routine function "main" in=0 out=0 entry=main
main:
  JLINES fused 9
  RET
fused:
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMPLN main 3
)");
  ASSERT_EQ(ops_of(image), (std::vector<Op>{Op::JLINES, Op::RET, Op::INCGJMPLN}))
      << bytecode::disassemble(image);
  const uint32_t step = image.code[4];
  EXPECT_EQ(bytecode::loop_step_global(step), 0u);
  EXPECT_EQ(bytecode::loop_step_step(step), 1);
  EXPECT_EQ(bytecode::loop_step_lines(step), 4u);
}

TEST(Peephole, NeverFusesAcrossAPlaceControlCanEnter) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "g" 1
.routine function "main" in=0 out=0 entry=main
.local int "i"
main:
  LDL 0
middle:
  PUSHI 3
  REMI
  STG g
  LDL 0
  JZ middle2
middle2:
  RET
)"));
  bytecode::Image image = p.image;
  image.routines.push_back({"other", bytecode::RoutineKind::Label, 0, 0, {}, 1});
  bytecode::optimize(image);
  // `middle` is a routine entry: LDL; PUSHI; REMI is not REMLK. PUSHI; REMI, which starts
  // there, may fuse (REMIK), and the entry then is the fused instruction's.
  EXPECT_EQ(ops_of(image)[0], Op::LDL);
  EXPECT_EQ(ops_of(image)[1], Op::REMIK);
  EXPECT_EQ(image.routines[1].entry, 1u);
}

TEST(Peephole, RelocatesLinesEntriesAndTargets) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kLoop));
  bytecode::Image image = p.image;
  image.lines = {{0, "f", 1}, {5, "f", 2}, {22, "f", 4}};
  bytecode::optimize(image);
  ASSERT_EQ(image.lines.size(), 3u);
  EXPECT_EQ(image.lines[0].code, 0u);
  EXPECT_EQ(image.lines[1].code, 4u);  // the loop top: the EOL before it is now a mark
  EXPECT_EQ(image.routines[0].entry, 0u);
}

}  // namespace
}  // namespace uprog::test

namespace uprog::test {
namespace {

TEST(Peephole, FusesLocalArithmeticAndThreadsJumps) {
  const char* text = R"(
.global float "out" 1
.routine function "main" in=0 out=0 entry=main
.local float "a"
.local float "b"
.local float "c"
.routine function "f" in=0 out=1 entry=f
.local int "r"
main:
  PUSHK 0
  STL 0
  PUSHK 1
  STL 1
  LDL 0
  LDL 1
  SUBF
  STL 2
  LDL 2
  LDL 0
  MULF
  STG out
  LDL 2
  STL 0
  JMP hop
hop:
  JMP done
done:
  RET
f:
  PUSHI 4
  STL 0
  EOL
  JMP leave
leave:
  RET
.const float 1.5
.const float 4.0
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {Op::STLK,    Op::STLK,     // a = 1.5, b = 4.0
                                    Op::SUBFLLS,               // c = a - b
                                    Op::MULFLL,  Op::STG,      // out = c * a
                                    Op::MOVL,                  // a = c
                                    Op::RET,                   // the jumps to hop and done: gone
                                    Op::PUSHI,   Op::STLJEOL,  // r = 4, end of line, to leave
                                    Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "locals");
}

// `if (a < b)` and `if (a >= 0.5)` on float locals: one instruction each, NaN included (q).
TEST(Peephole, FusesFloatComparesOnLocals) {
  const char* text = R"(
.global int "count" 1
.routine function "main" in=0 out=0 entry=main
.local float "a"
.local float "b"
.local float "q"
main:
  PUSHK 0
  STL 0
  PUSHK 1
  STL 1
  PUSHK 2
  STL 2
  LDL 0
  LDL 1
  LTF
  JZ skip1
  PUSHI 1
  STG count
skip1:
  LDL 2
  PUSHK 0
  GEF
  JZ skip2
  PUSHI 2
  STG count
skip2:
  LDL 0
  PUSHK 0
  GEF
  JZ skip3
  LDG count
  PUSHI 10
  ADDI
  STG count
skip3:
  RET
.const float 0.5
.const float 4.0
.const float bits 2143289344
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {Op::STLK,    Op::STLK, Op::STLK,
                                    Op::JNLTFLL, Op::STGK,  // a < b: count = 1
                                    Op::JNGEFLK, Op::STGK,  // q >= 0.5: NaN, skipped
                                    Op::JNGEFLK, Op::INCG,  // a >= 0.5: count += 10
                                    Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "float compares");
  EXPECT_EQ(run_and_read(image, "count"), 11);
}

// `for k = 1:3 ... end` steps and jumps back in one instruction; `x = 0.5` stores a constant;
// an if arm's last assignment ends its line and jumps past the else.
TEST(Peephole, FusesLineEndingJumpsAndConstantStores) {
  const char* text = R"(
.global int "total" 1
.routine function "main" in=0 out=0 entry=main
.local int "k"
.local float "x"
main:
  PUSHK 0
  STL 1
  EOL
  PUSHI 1
  STL 0
head:
  LDL 0
  PUSHI 3
  GTI
  JNZ done
  LDG total
  LDL 0
  ADDI
  STG total
  EOL
  INCL 0 1
  EOL
  JMP head
done:
  LDG total
  PUSHI 6
  EQI
  JZ other
  PUSHI 100
  STL 0
  EOL
  JMP end
other:
  PUSHI 200
  STL 0
  EOL
end:
  LDL 0
  STG total
  RET
.const float 0.5
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {Op::STLK,     Op::EOL,      Op::PUSHI, Op::STL,
                                    Op::JGTLK,                   // k > 3
                                    Op::LDL,      Op::ADDIGEOL,  // total += k
                                    Op::INCLJEOL,                // k += 1; back
                                    Op::JNEGK,                   // total == 6
                                    Op::PUSHI,    Op::STLJEOL,   // k = 100; to end
                                    Op::PUSHI,    Op::STL,      Op::LDL,   Op::STG, Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  // STLK is a superinstruction, which carries no mark: its EOL stays.
  EXPECT_EQ(marked_ops(image), (std::vector<Op>{Op::STL})) << bytecode::disassemble(image);
  expect_same_behaviour(text, "line-ending jumps");
  EXPECT_EQ(run_and_read(image, "total"), 100);
}

// How many slices of one line each `image` takes from routine 0 to its end: the fused line
// ends (STGEOL, STGJEOL, ...) must end exactly the lines that EOL did.
uint64_t line_slices(const bytecode::Image& image) {
  LoadedProgram loaded;
  EXPECT_TRUE(loaded.load(bytecode::disassemble(image)));
  loaded.machine.start(0, 0);
  uint64_t slices = 0;
  for (; slices < 100000; ++slices) {
    const vm::SliceResult r = loaded.machine.run_slice(0, vm::Budget::of_lines(1));
    if (r.end != vm::SliceEnd::LineEnd) break;
  }
  return slices;
}

// The optimized `image` of `text` ends its lines where the plain code does.
void expect_same_line_ends(const char* text, const bytecode::Image& image) {
  LoadedProgram plain;
  ASSERT_TRUE(plain.load(text));
  EXPECT_EQ(line_slices(image), line_slices(plain.image));
}

// A loop whose variables are all globals, as PDL and ST compile theirs: the global forms of
// compare-and-branch, constant arithmetic, increment, pairs, and the stores that end a line.
TEST(Peephole, FusesGlobals) {
  const char* text = R"(
.global int "i" 1
.global int "s" 1
.global int "r" 1
.global float "p" 1
.global float "v" 1
.const int 100
.const float 0.5
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG i
  EOL
  PUSHK 1
  STG v
  EOL
  PUSHK 1
  STG p
  EOL
top:
  LDG i
  PUSHK 0
  GTI
  JNZ done
  EOL
  LDG i
  PUSHI 3
  REMI
  STG r
  EOL
  LDG r
  PUSHI 0
  NEI
  JZ skip
  LDG s
  LDG r
  ADDI
  STG s
  EOL
  JMP next
skip:
  LDG p
  LDG v
  MULF
  STG p
next:
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMP top
done:
  LDG p
  PUSHK 1
  LTF
  JZ end
  LDG s
  LDG i
  MULI
  STG r
  LDG i
  PUSHI 5
  SUBI
  STG s
  LDG r
  PUSHI 7
  LEI
  JNZ end
  PUSHI 1
  STG v
end:
  RET
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {
      Op::STGKEOL,                         // i = 1 (the immediate as a constant)
      Op::STGKEOL,                         // v = 0.5
      Op::STGKEOL,                         // p = 0.5
      Op::JGTGK,    Op::EOL,               // while i <= 100 (the constant 100)
      Op::REMGKEOL,                        // r = i % 3
      Op::JZG,                             // if r <> 0
      Op::ADDIGG,   Op::STGJEOL,           // s = s + r; end of line, to next (STGJEOL, not EOL)
      Op::MULFGG,   Op::STG,               // skip: p = p * v (next: is a target)
      Op::INCG,     Op::JMPEOL,            // next: i = i + 1; end of line, back to top
      Op::JNLTFGK,                         // done: if p < 0.5
      Op::LDG2,     Op::MULI,    Op::STG,  // r = s * i
      Op::ADDGK,    Op::STG,               // s = i - 5
      Op::JLEGK,                           // if r > 7 (the immediate 7 as an added constant)
      Op::STGK,                            // v = 1
      Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  // The immediates 1 (stored twice) and 7 became constants of their own; 100 and 0.5 were
  // there already.
  ASSERT_EQ(image.constants.size(), 4u);
  EXPECT_EQ(static_cast<int32_t>(image.constants[2].bits), 1);
  EXPECT_EQ(static_cast<int32_t>(image.constants[3].bits), 7);
  expect_same_behaviour(text, "globals");
  EXPECT_EQ(run_and_read(image, "r"), 100 * 101);  // s = 100 (i % 3 summed), i = 101
  EXPECT_EQ(run_and_read(image, "s"), 96);
  EXPECT_EQ(run_and_read(image, "v"), 1);
  expect_same_line_ends(text, image);
}

// A counter's step and a constant's store that end their lines (PDL's `n++;` and `f=0.0;`) are
// one instruction each, ending the same lines; before a JMP the EOL goes with the JMP instead.
TEST(Peephole, EndsLinesWithACounterAndAConstant) {
  const char* text = R"(
.global int "n" 1
.global int "m" 1
.global float "f" 1
.const float 0.0
.routine function "main" in=0 out=0 entry=main
main:
top:
  LDG n
  PUSHI 5
  GEI
  JNZ done
  EOL
  PUSHK 0
  STG f
  EOL
  LDG n
  PUSHI 1
  ADDI
  STG n
  EOL
  LDG n
  STG m
  EOL
  JMP top
done:
  RET
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {Op::JGEGK,   Op::EOL,     // while n < 5
                                    Op::STGKEOL,              // f = 0.0
                                    Op::INCGEOL,              // n = n + 1
                                    Op::MOVG,    Op::JMPEOL,  // m = n; end of line, back to top
                                    Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "line-ending counter and constant");
  EXPECT_EQ(run_and_read(image, "n"), 5);
  EXPECT_EQ(run_and_read(image, "m"), 5);
  expect_same_line_ends(text, image);
  EXPECT_EQ(line_slices(image), 5u * 4);  // four lines a turn; the last test jumps to the end
}

// A condition's line ends after its branch on both paths (PDL's `if` and `while`): "Jcc T; EOL"
// with an EOL at T is one branch that ends the line and jumps past T's EOL, for each family of
// fused branches; the lines end where they did.
TEST(Peephole, BranchesEndTheirLines) {
  const char* text = R"(
.global int "i" 1
.global int "s" 1
.global int "r" 1
.global float "p" 1
.global float "q" 1
.const float 0.5
.const float 1.0
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  STG i
  EOL
  PUSHK 1
  STG q
  EOL
top:
  LDG i
  PUSHI 10
  GEI
  JNZ done
  EOL
  LDG p
  PUSHK 0
  GEF
  JZ else1
  EOL
  LDG s
  PUSHI 1
  ADDI
  STG s
  EOL
  JMP join1
else1:
  EOL
  LDG p
  PUSHK 0
  ADDF
  STG p
  EOL
join1:
  LDG p
  LDG q
  LTF
  JZ skip2
  EOL
  PUSHI 1
  STG r
  EOL
skip2:
  EOL
  LDG r
  JZ skip3
  EOL
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMP top
skip3:
  EOL
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMP top
done:
  EOL
  RET
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {
      Op::STGKEOL,                 // i = 0
      Op::STGKEOL,                 // q = 1.0
      Op::JGEGKEOL,                // while i < 10
      Op::JNGEFGKEOL,              // if p >= 0.5
      Op::INCG,       Op::JMPEOL,  // s = s + 1 (else1's EOL: dropped)
      Op::ADDFGK,     Op::STGEOL,  // p = p + 0.5
      Op::JNLTFGGEOL,              // join1: if p < q
      Op::STGKEOL,                 // r = 1
      Op::EOL,                     // skip2
      Op::JZGEOL,                  // if r
      Op::INCG,       Op::JMPEOL,  // i = i + 1
      Op::INCG,       Op::JMPEOL,  // skip3 (its EOL dropped): i = i + 1
      Op::RET};                    // done (its EOL dropped)
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "branches that end their lines");
  EXPECT_EQ(run_and_read(image, "i"), 10);
  EXPECT_EQ(run_and_read(image, "s"), 9);  // p reaches 0.5 in the first turn's else
  EXPECT_EQ(run_and_read(image, "r"), 1);
  expect_same_line_ends(text, image);
}

// Where the branch's target EOL starts a source line, the branch still goes to it: a breakpoint
// on that line must be hit on the way.
TEST(Peephole, BranchesKeepATargetThatStartsALine) {
  const bytecode::Image image = optimized(R"(
.global int "g" 1
.routine function "main" in=0 out=0 entry=main
.line "t.pdl" 1
main:
  LDG g
  JZ other
  EOL
.line "t.pdl" 2
other:
  EOL
  RET
)");
  const std::vector<Op> expected = {Op::JZG, Op::EOL, Op::EOL, Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
}

// The three-address forms of a loop over globals (PDL's and ST's variables): two globals'
// arithmetic stored, a remainder by a 16-bit constant stored, a global's accumulation of a fused
// expression, a float global with a constant, two float globals compared. The same lines end.
TEST(Peephole, FusesThreeAddressGlobals) {
  const char* text = R"(
.global int "i" 1
.global int "s" 1
.global int "r" 1
.global int "d" 1
.global float "p" 1
.global float "q" 1
.global float "v" 1
.global float "t" 1
.const float 0.5
.const float 2.0
.routine function "main" in=0 out=0 entry=main
main:
  PUSHK 1
  STG v
  EOL
top:
  LDG i
  PUSHI 12
  GEI
  JNZ done
  EOL
  LDG i
  LDG s
  SUBI
  STG d
  EOL
  LDG i
  PUSHI 5
  REMI
  STG r
  EOL
  LDG i
  PUSHI 100000
  REMI
  STG d
  EOL
  LDG s
  LDG i
  PUSHI 7
  REMI
  ADDI
  STG s
  EOL
  LDG p
  LDG v
  PUSHK 0
  MULF
  ADDF
  STG p
  EOL
  LDG q
  LDG p
  LDG v
  MULF
  SUBF
  STG q
  EOL
  LDG p
  LDG v
  PUSHK 0
  MULF
  ADDF
  STG t
  EOL
  LDG p
  LDG q
  ADDF
  STG t
  EOL
  PUSHK 1
  LDG t
  MULF
  STG t
  EOL
  LDG t
  PUSHK 1
  SUBF
  STG t
  EOL
  LDG p
  LDG q
  GTF
  JZ next
  LDG t
  PUSHK 0
  ADDF
  STG t
next:
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMP top
done:
  RET
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {
      Op::STGKEOL,                  // v = 2.0
      Op::JGEGK,     Op::EOL,       // while i < 12
      Op::SUBIGGEOL,                // d = i - s
      Op::REMGKEOL,                 // r = i % 5
      Op::REMGK,     Op::STGEOL,    // d = i % 100000: beyond a 16-bit immediate
      Op::REMGK,     Op::ADDIGEOL,  // s = s + i % 7
      Op::MULFGK,    Op::ADDFGEOL,  // p = p + v * 0.5
      Op::MULFGG,    Op::SUBFGEOL,  // q = q - p * v
      Op::LDG,       Op::MULFGK,   Op::ADDF, Op::STGEOL,  // t = p + v * 0.5: t is not p
      Op::ADDFGGEOL,                                      // t = p + q
      Op::MULFKG,    Op::STGEOL,                          // t = 2.0 * t
      Op::SUBFGK,    Op::STGEOL,                          // t = t - 2.0
      Op::JNGTFGG,                                        // if p > q
      Op::ADDFGK,    Op::STG,                             // t = t + 0.5
      Op::INCG,      Op::JMPEOL,                          // next: i = i + 1
      Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "three-address globals");
  EXPECT_EQ(run_and_read(image, "i"), 12);
  expect_same_line_ends(text, image);
}

// A frame in the data memory, as PDL compiles a procedure's parameters and locals (fp is
// local 0): its words read and written at fp plus a constant, the address computed after a
// value that writes nothing; a pointer's range tests keep the pointer. `*r = n - 1` through a
// pointer into the frame; the same lines end.
TEST(Peephole, FusesFramesInTheDataMemory) {
  const char* text = R"(
.global int "user" 4
.global int "frame" 4
.global int "seen" 1
.routine function "main" in=0 out=0 entry=main
.local int "fp"
.local int "base"
main:
  PUSHI 4
  STL 0
  PUSHI 4
  STL 1
  ADDLK 0 1
  PUSHI 7
  STM
  EOL
  ADDLK 0 2
  LDL 1
  PUSHI 2
  ADDI
  STM
  EOL
  ADDLK 0 2
  LDM
  DUP
  PUSHI 4
  CMPU 2
  JNZ flat
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ flat
  RAISE 15
flat:
  ADDLK 0 1
  LDM
  PUSHI 1
  SUBI
  STM
  EOL
  ADDLK 0 0
  ADDLK 0 3
  LDM
  STM
  PUSHI 8
  ADDLK 0 1
  LDM
  STM
  EOL
  ADDLK 0 1
  LDM
  PUSHI 7
  LTI
  JZ big
  EOL
  PUSHI 8
  PUSHI 1
  STM
  EOL
big:
  EOL
  RET
)";
  constexpr uint32_t kGreaterOrEqual = 5;  // == != < <= > >=
  // The code words move: flat from 30 to 16; "JZ big; EOL" with big's EOL ends the line on
  // both paths, so the fused branch goes past big's EOL, to the RET (61, then 33).
  // Each rewrite beside the base lines it replaces, as a table.
  // clang-format off
  const bytecode::Image image = expect_listing(text, {
      {{"L0:", "PUSHI 4", "STL 0", "PUSHI 4", "STL 1"},
       {"L0:", "PUSHI 4", "STL 0", "PUSHI 4", "STL 1"}},
      // frame[1] = 7: the value first, then the store at the frame's word
      {{"PUSHI 7", "STMLK 0 1", "EOL"}, {"ADDLK 0 1", "PUSHI 7", "STM", "EOL"}},
      // frame[2] = base + 2 (a pointer: 6)
      {{"ADDLK 1 2", "STMLK 0 2", "EOL"}, {"ADDLK 0 2", "LDL 1", "PUSHI 2", "ADDI", "STM", "EOL"}},
      // r = frame[2], in the user memory (below 4) or the frame (base + 0..3)
      {{with_b("LDPMLK L16", bytecode::pack_pointer_test(0, 2, 4, 1, 2))},
       {"ADDLK 0 2", "LDM", "DUP", "PUSHI 4", "CMPU 2", "JNZ L30", "DUP", "LDL 1", "SUBI",
        "PUSHI 4", "CMPU 2", "JNZ L30"}},
      {{"RAISE 15"}, {"RAISE 15"}},
      // flat: *r = frame[1] - 1, the STM carrying the line's end
      {{"L16:", with_b("ADDMLK 0", bytecode::pack_local_imm(1, -1)), "STM.eol"},
       {"L30:", "ADDLK 0 1", "LDM", "PUSHI 1", "SUBI", "STM", "EOL"}},
      // frame[0] = frame[3]
      {{"LDMLK 0 3", "STMLK 0 0"}, {"ADDLK 0 0", "ADDLK 0 3", "LDM", "STM"}},
      // seen = frame[1]: the address first
      {{"PUSHI 8", "LDMLK 0 1", "STM.eol"}, {"PUSHI 8", "ADDLK 0 1", "LDM", "STM", "EOL"}},
      // if (frame[1] < 7), ending its line either way
      {{with_b("JCMPMKEOL L33", bytecode::pack_frame_test(0, 1, kGreaterOrEqual, 7))},
       {"ADDLK 0 1", "LDM", "PUSHI 7", "LTI", "JZ L60", "EOL"}},
      // seen = 1 (not run: frame[1] is 7)
      {{"PUSHI 8", "PUSHI 1", "STM.eol"}, {"PUSHI 8", "PUSHI 1", "STM", "EOL"}},
      // big's EOL, after the body: it falls into it
      {{"EOL"}, {"L60:", "EOL"}},
      {{"L33:", "RET"}, {"RET"}},
  });
  // clang-format on
  EXPECT_EQ(run_and_read(image, "seen"), 7);
  expect_same_line_ends(text, image);
}

// `n--;` of a parameter kept in the data memory: the word read, stepped and stored at the same
// address, then the line's end, is one instruction that ends the line.
TEST(Peephole, StepsAFrameWordInItsLine) {
  const char* text = R"(
.global int "frame" 4
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 1
  STL 0
  EOL
  ADDLK 0 2
  ADDLK 0 2
  LDM
  PUSHI 1
  SUBI
  STM
  EOL
  RET
)";
  // Each rewrite beside the base lines it replaces, as a table.
  // clang-format off
  const bytecode::Image image = expect_listing(text, {
      {{"L0:", "PUSHI 1", "STL.eol 0"}, {"L0:", "PUSHI 1", "STL 0", "EOL"}},
      {{with_b("INCMLKEOL 0", bytecode::pack_local_imm(2, -1))},
       {"ADDLK 0 2", "ADDLK 0 2", "LDM", "PUSHI 1", "SUBI", "STM", "EOL"}},
      {{"RET"}, {"RET"}},
  });
  // clang-format on
  LoadedProgram fused;
  ASSERT_TRUE(fused.load(bytecode::disassemble(image)));
  fused.machine.start(0, 0);
  fused.run_to_end();
  EXPECT_EQ(fused.global("frame", 3).i, -1);  // the word at fp + 2: 0 - 1
  expect_same_line_ends(text, image);
}

// An `if` without `else` as PDL and ST compile it: the condition's line ends on both paths
// ("JZ f; EOL" and an EOL at f), the body jumps past f's EOL. Once the branch ends its line
// and jumps past that EOL too, nothing reaches it: it is dropped, the body's jump then goes
// to what follows and falls through, and `s = s + r` is one three-address instruction.
TEST(Peephole, DropsWhatNothingReaches) {
  const char* text = R"(
.global int "i" 1
.global int "r" 1
.global int "s" 1
.routine function "main" in=0 out=0 entry=main
main:
top:
  LDG i
  PUSHI 9
  GTI
  JNZ done
  EOL
  LDG i
  PUSHI 3
  REMI
  STG r
  EOL
  LDG r
  JZ f
  EOL
  LDG s
  LDG r
  ADDI
  STG s
  EOL
  JMP end
f:
  EOL
end:
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMP top
done:
  RET
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {
      Op::JGTGK,     Op::EOL,  // while i <= 9
      Op::REMGKEOL,            // r = i % 3
      Op::JZGEOL,              // if r: to end, the line ended (f's EOL is dropped)
      Op::ADDIGGEOL,           // s = s + r, falling through to end
      Op::INCG,      Op::JMPEOL, Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "dead code");
  EXPECT_EQ(run_and_read(image, "s"), 9);  // 1 + 2 + 0, three times
  expect_same_line_ends(text, image);
}

// ST's `IF R3 = 3 THEN R3 := 0; END_IF;`: the THEN arm's line ends, then its jump over the
// ELSE side's EOL, which nothing reaches once the condition's branch ends its line. The
// immediate's store becomes a constant's (a constant of its own), and with the jump gone the
// EOL merges into it: the arm is one STGKEOL.
TEST(Peephole, EndsAnArmInItsStore) {
  const char* text = R"(
.global int "i" 1
.global int "r" 1
.routine function "main" in=0 out=0 entry=main
main:
top:
  LDG i
  PUSHI 9
  GTI
  JNZ done
  EOL
  LDG r
  PUSHI 1
  ADDI
  STG r
  EOL
  LDG r
  PUSHI 3
  EQI
  JZ other
  EOL
  PUSHI 0
  STG r
  EOL
  JMP end
other:
  EOL
end:
  LDG i
  PUSHI 1
  ADDI
  STG i
  EOL
  JMP top
done:
  RET
)";
  const bytecode::Image image = optimized(text);
  const std::vector<Op> expected = {Op::JGTGK,    Op::EOL,  // while i <= 9
                                    Op::INCGEOL,            // r = r + 1
                                    Op::JNEGKEOL,           // if r = 3: the line ends on both paths
                                    Op::STGKEOL,            // r = 0
                                    Op::INCG,     Op::JMPEOL, Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  expect_same_behaviour(text, "an arm ended in its store");
  EXPECT_EQ(run_and_read(image, "r"), 1);  // ten steps: 1, 2, 0, 1, 2, 0, 1, 2, 0, 1
  expect_same_line_ends(text, image);
}

// No global form is made across a place control can enter: `inside` is a routine's entry.
TEST(Peephole, NeverFusesGlobalsAcrossAnEntry) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.global int "g" 1
.global int "h" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG g
inside:
  PUSHI 1
  ADDI
  STG g
  LDG h
  JZ inside2
inside2:
  LDG g
  STG h
  EOL
  RET
)"));
  bytecode::Image image = p.image;
  image.routines.push_back({"other", bytecode::RoutineKind::Label, 0, 0, {}, 1});
  bytecode::optimize(image);
  // After inside2 (entered), `LDG g; STG h; EOL` is one move that ends the line.
  const std::vector<Op> expected = {Op::LDG, Op::PUSHI, Op::ADDI, Op::STG,
                                    Op::JZG, Op::MOVG,  Op::RET};
  EXPECT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
}

// The waits of `until (command <test>)`, with a comparison (kept, or negated for JZ) or a bare
// test against 0, become UNTILCK; the plain and the fused program take the same slices and
// read the command as often. Command 5 counts its reads; command 1's register 0 starts at 0.
const char* kWaits = R"(
.global int "reached" 1
.routine function "main" in=0 out=0 entry=main
main:
w1:
  CMDGET 5 0
  PUSHI 3
  GEI
  JNZ d1          ; on when the count >= 3
  YIELD
  JMP w1
d1:
  PUSHI 1
  STG reached
w2:
  CMDGET 5 0
  PUSHI 6
  LTI
  JZ d2           ; on when not count < 6
  YIELD
  JMP w2
d2:
  CMDGET 1 0
  JZ d3           ; on when register 0 == 0
  YIELD
  JMP d2
d3:
  PUSHI 1
  CMDSET 1 0
w4:
  CMDGET 1 0
  JNZ d4          ; on when register 0 != 0
  YIELD
  JMP w4
d4:
  RET
)";

TEST(Peephole, WaitsOnACommandInPlace) {
  const bytecode::Image image = optimized(kWaits);
  const std::vector<Op> expected = {Op::UNTILCK, Op::STGK,   Op::UNTILCK, Op::UNTILCK,
                                    Op::PUSHI,   Op::CMDSET, Op::UNTILCK, Op::RET};
  ASSERT_EQ(ops_of(image), expected) << bytecode::disassemble(image);
  std::vector<uint32_t> tests;
  for (uint32_t pc = 0; pc < image.code.size();
       pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
    if (bytecode::word_op(image.code[pc]) == Op::UNTILCK) tests.push_back(image.code[pc + 1]);
  const std::vector<uint32_t> packed = {bytecode::pack_command_test(0, 5, 3),   // >= 3
                                        bytecode::pack_command_test(0, 5, 6),   // >= 6
                                        bytecode::pack_command_test(0, 0, 0),   // == 0
                                        bytecode::pack_command_test(0, 1, 0)};  // != 0
  EXPECT_EQ(tests, packed);

  LoadedProgram plain;
  ASSERT_TRUE(plain.load(kWaits));
  LoadedProgram fused;
  ASSERT_TRUE(fused.load(bytecode::disassemble(image)));
  for (LoadedProgram* p : {&plain, &fused}) {
    p->machine.start(0, 0);
    EXPECT_EQ(p->run_to_end().end, vm::SliceEnd::Finished);
  }
  EXPECT_EQ(plain.slices, 5u);  // reads 1 2 3 | 4 | 5 | 6 and on
  EXPECT_EQ(fused.slices, plain.slices);
  EXPECT_EQ(plain.host.counter_reads, 6);
  EXPECT_EQ(fused.host.counter_reads, plain.host.counter_reads);
  EXPECT_EQ(fused.global("reached").i, 1);
}

// Not a wait: the JMP goes elsewhere, the branch's target is not after the JMP, an index beyond
// 255, an immediate beyond 20 bits.
TEST(Peephole, LeavesOtherLoopsAlone) {
  const bytecode::Image image = optimized(R"(
.routine function "main" in=0 out=0 entry=main
main:
  NOP
w1:
  CMDGET 1 0
  JZ d1
  YIELD
  JMP main
d1:
  CMDGET 1 0
  JZ w1
  YIELD
  JMP d1
w3:
  CMDGET 1 256
  JZ d3
  YIELD
  JMP w3
d3:
  CMDGET 1 0
  PUSHI 524288
  EQI
  JNZ d4
  YIELD
  JMP d3
d4:
  RET
)");
  for (const Op op : ops_of(image)) EXPECT_NE(op, Op::UNTILCK) << bytecode::disassemble(image);
}

// Code with line-end marks (a CUP image) is one instruction a line: fusing "LDG; PUSHI; ADDI;
// STG" would merge four lines into one, so the pass leaves it alone.
TEST(Peephole, LeavesMarkedCodeAsItIs) {
  const char* marked = R"(
.global int "n" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG.eol n
  PUSHI.eol 1
  ADDI.eol
  STG.eol n
  RET
)";
  LoadedProgram p;
  ASSERT_TRUE(p.load(marked));
  const bytecode::Image image = optimized(marked);
  EXPECT_EQ(image.code, p.image.code);
  // Unmarked, the same four instructions fuse.
  const std::string plain = std::regex_replace(marked, std::regex(R"(\.eol)"), "");
  EXPECT_LT(ops_of(optimized(plain)).size(), ops_of(p.image).size());
}

}  // namespace
}  // namespace uprog::test
