// The compile-time pass (bytecode/peephole.cpp) changes no behaviour: every VM case runs to the
// same end with the same globals before and after it. It makes base instructions only: a
// comparison and its branch one compare-and-jump, a line's end a mark or a jump's, and it drops
// what nothing reaches; never across a place control can enter. Listings compare line by line.
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

std::string read(const fs::path& p) { return read_whole(p); }

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

// One step of the pass's listing: the lines it makes (`fused`) of the lines before them (`base`).
struct Rewrite {
  std::vector<std::string> fused;
  std::vector<std::string> base;
};

// Compares the listing of `text` before and after the pass line by line: the code before is the
// rewrites' base lines in order, the code after their `fused` lines, and the first line that
// differs is named with the rewrite it belongs to. Then the code after must behave as the code
// before does. Returns the image after.
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

TEST(Peephole, EveryCaseBehavesTheSame) {
  for (const auto& e : fs::directory_iterator(fs::path(UPROG_SOURCE_DIR) / "tests/vm/cases"))
    expect_same_behaviour(read(e.path()), e.path().stem().string());
}

// Every image the pass makes holds base opcodes only.
bool base_only(const bytecode::Image& image) {
  for (uint32_t pc = 0; pc < image.code.size();
       pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
    if ((image.code[pc] & 0xFFu) >= bytecode::kBaseOpCount) return false;
  return true;
}

// A loop as the compilers write it: comparisons before JZ/JNZ, EOLs, a test against 0.
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
  CMPI 3
  JZ done
  LDL 0
  PUSHI 3
  REMI
  PUSHI 0
  CMPI 1
  JZ next
  LDG total
  LDL 0
  ADDI
  STG total
  EOL
next:
  LDL 0
  PUSHI 50
  CMPI 4
  JNZ skip
  LDG x
  PUSHK 0
  CMPF 2
  JZ skip
  LDG x
  PUSHK 0
  ADDF
  STG x
skip:
  INCL 0 1
  EOL
  JMP top
done:
  RET
)";

TEST(Peephole, ComparesAndJumpsInOneAndEndsLinesOnTheirLastInstruction) {
  const bytecode::Image image = expect_listing(
      kLoop,
      {{{"L0:", "PUSHI 1", "STL 0", "PUSHI 100", "STL.eol 1"},
        {"L0:", "PUSHI 1", "STL 0", "PUSHI 100", "STL 1", "EOL"}},
       // i <= n, or out: the branch jumps when the comparison fails
       {{"L4:", "LDL 0", "LDL 1", "JGTI L28"}, {"L5:", "LDL 0", "LDL 1", "CMPI 3", "JZ L36"}},
       // i % 3 != 0, or next: the test against 0 is the branch itself
       {{"LDL 0", "PUSHI 3", "REMI", "JZ L15"},
        {"LDL 0", "PUSHI 3", "REMI", "PUSHI 0", "CMPI 1", "JZ L20"}},
       // total = total + i, its line's end a mark
       {{"LDG 0", "LDL 0", "ADDI", "STG.eol 0"}, {"LDG 0", "LDL 0", "ADDI", "STG 0", "EOL"}},
       // i > 50 jumps as it was true; a float comparison jumps "unless"
       {{"L15:", "LDL 0", "PUSHI 50", "JGTI L25", "LDG 1", "PUSHK 0", "JNLTF L25"},
        {"L20:", "LDL 0", "PUSHI 50", "CMPI 4", "JNZ L32", "LDG 1", "PUSHK 0", "CMPF 2", "JZ L32"}},
       {{"LDG 1", "PUSHK 0", "ADDF", "STG 1"}, {"LDG 1", "PUSHK 0", "ADDF", "STG 1"}},
       // the step's line ends in the jump back
       {{"L25:", "INCL 0 1", "JMP.eol L4"}, {"L32:", "INCL 0 1", "EOL", "JMP L5"}},
       {{"L28:", "RET"}, {"L36:", "RET"}}});
  EXPECT_TRUE(base_only(image));
}

TEST(Peephole, NeverMergesAcrossAPlaceControlCanEnter) {
  // `middle` is a jump target: the CMPI before it and the JZ there stay apart.
  const char* text = R"(
.global int "g" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG g
  PUSHI 3
  CMPI 2
middle:
  JZ out
  LDG g
  PUSHI 1
  ADDI
  STG g
  LDG g
  PUSHI 3
  CMPI 2
  JMP middle
out:
  RET
)";
  const std::vector<std::string> unchanged = {
      "L0:",  "LDG 0", "PUSHI 3", "CMPI 2",  "L3:",    "JZ L12", "LDG 0", "PUSHI 1",
      "ADDI", "STG 0", "LDG 0",   "PUSHI 3", "CMPI 2", "JMP L3", "L12:",  "RET"};
  expect_listing(text, {{unchanged, unchanged}});
  EXPECT_EQ(run_and_read(optimized(text), "g"), 3);
}

TEST(Peephole, StepsALocalByAConstantInOneInstruction) {
  // `n = n + 3` of a local is INCL, the line's end its mark (both wrap); `m = n + 1` stays as it
  // is. n counts 5 + 3 and 2147483647 + 1 wraps to -2147483648.
  const char* text = R"(
.global int "r" 3
.const int 2147483647
.routine function "main" in=0 out=0 entry=main
.local int "n"
.local int "m"
main:
  PUSHI 5
  STL 0
  LDL 0
  PUSHI 3
  ADDI
  STL.eol 0
  LDL 0
  PUSHI 1
  ADDI
  STL 1
  PUSHI 0
  LDL 0
  STGX r
  PUSHI 1
  LDL 1
  STGX r
  PUSHK 0
  STL 0
  LDL 0
  PUSHI 1
  ADDI
  STL 0
  PUSHI 2
  LDL 0
  STGX r
  RET
)";
  const std::vector<std::string> first = {"L0:", "PUSHI 5", "STL 0"};
  const std::vector<std::string> other = {"LDL 0",   "PUSHI 1", "ADDI",    "STL 1",
                                          "PUSHI 0", "LDL 0",   "STGX 0",  "PUSHI 1",
                                          "LDL 1",   "STGX 0",  "PUSHK 0", "STL 0"};
  const std::vector<std::string> last = {"PUSHI 2", "LDL 0", "STGX 0", "RET"};
  const bytecode::Image image =
      expect_listing(text, {{first, first},
                            {{"INCL.eol 0 3"}, {"LDL 0", "PUSHI 3", "ADDI", "STL.eol 0"}},
                            {other, other},
                            {{"INCL 0 1"}, {"LDL 0", "PUSHI 1", "ADDI", "STL 0"}},
                            {last, last}});
  EXPECT_TRUE(base_only(image));
  LoadedProgram loaded;
  ASSERT_TRUE(loaded.load(bytecode::disassemble(image)));
  loaded.machine.start(0, 0);
  loaded.run_to_end();
  EXPECT_EQ(loaded.global("r", 0).i, 8);
  EXPECT_EQ(loaded.global("r", 1).i, 9);
  EXPECT_EQ(loaded.global("r", 2).i, INT32_MIN);
}

TEST(Peephole, SubtractsAnImmediateAsTheAdditionOfItsNegation) {
  // `g = g - 3` of a global is `PUSHI -3; ADDI` (both wrap: the VM's fused forms of an immediate
  // take it), and of a local then INCL by -2; -(-4194304) is no immediate, so that SUBI stays,
  // and so does one whose PUSHI ends a line. g: 10 - 3 = 7; n: 5 - 2 = 3; 7 - -4194304 =
  // 4194311; 7 - 1 = 6.
  const char* text = R"(
.global int "g" 1
.global int "r" 3
.routine function "main" in=0 out=0 entry=main
.local int "n"
main:
  PUSHI 10
  STG g
  LDG g
  PUSHI 3
  SUBI
  STG g
  PUSHI 5
  STL 0
  LDL 0
  PUSHI 2
  SUBI
  STL 0
  PUSHI 0
  LDL 0
  STGX r
  PUSHI 1
  LDG g
  PUSHI -4194304
  SUBI
  STGX r
  PUSHI 2
  LDG g
  PUSHI.eol 1
  SUBI
  STGX r
  RET
)";
  const std::vector<std::string> first = {"L0:", "PUSHI 10", "STG 0", "LDG 0"};
  const std::vector<std::string> middle = {"STG 0", "PUSHI 5", "STL 0"};
  const std::vector<std::string> last = {"PUSHI 0",        "LDL 0", "STGX 1", "PUSHI 1", "LDG 0",
                                         "PUSHI -4194304", "SUBI",  "STGX 1", "PUSHI 2", "LDG 0",
                                         "PUSHI.eol 1",    "SUBI",  "STGX 1", "RET"};
  const bytecode::Image image =
      expect_listing(text, {{first, first},
                            {{"PUSHI -3", "ADDI"}, {"PUSHI 3", "SUBI"}},
                            {middle, middle},
                            {{"INCL 0 -2"}, {"LDL 0", "PUSHI 2", "SUBI", "STL 0"}},
                            {last, last}});
  EXPECT_EQ(run_and_read(image, "g"), 7);
  LoadedProgram loaded;
  ASSERT_TRUE(loaded.load(bytecode::disassemble(image)));
  loaded.machine.start(0, 0);
  loaded.run_to_end();
  EXPECT_EQ(loaded.global("r", 0).i, 3);
  EXPECT_EQ(loaded.global("r", 1).i, 4194311);
  EXPECT_EQ(loaded.global("r", 2).i, 6);
}

TEST(Peephole, DropsWhatNothingReachesAndThreadsJumps) {
  // `if (r) s = 1`: the condition's branch ends its line on both paths and jumps past the EOL at
  // its target, which then nothing reaches; the jump over it and the one after `end` end their
  // lines; code after a jump that nothing enters goes; a jump that ends its line before a RET
  // is RETEOL. Either way the same lines end: 2 when r is 0, 3 otherwise.
  const char* text = R"(
.global int "r" 1
.global int "s" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDG r
  JZ f
  EOL
  PUSHI 1
  STG s
  EOL
  JMP end
f:
  EOL
end:
  EOL
  JMP out
  PUSHI 7
  STG s
out:
  RET
)";
  const bytecode::Image image = expect_listing(
      text, {{{"L0:", "LDG 0", "JZ.eol L4"}, {"L0:", "LDG 0", "JZ L7"}},
             {{"PUSHI 1", "STG.eol 1"}, {"EOL", "PUSHI 1", "STG 1", "EOL", "JMP L8"}},
             {{"L4:", "RETEOL", "RET"},
              {"L7:", "EOL", "L8:", "EOL", "JMP L12", "PUSHI 7", "STG 1", "L12:", "RET"}}});
  EXPECT_TRUE(base_only(image));
}

TEST(Peephole, RelocatesLinesEntriesAndTargets) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kLoop));
  bytecode::Image image = p.image;
  image.lines = {{0, "f", 1}, {5, "f", 2}, {32, "f", 4}};
  bytecode::optimize(image);
  ASSERT_EQ(image.lines.size(), 3u);
  EXPECT_EQ(image.lines[0].code, 0u);
  EXPECT_EQ(image.lines[1].code, 4u);  // the loop top: the EOL before it is now a mark
  EXPECT_EQ(image.lines[2].code, 25u);
  EXPECT_EQ(image.routines[0].entry, 0u);
}

}  // namespace
}  // namespace uprog::test
