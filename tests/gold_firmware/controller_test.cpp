// The Controller: the acceptance move measured, bad input refused without harm, the program
// store and parameters persisted atomically, a corrupt stored image refused at boot.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "compile_bytes.h"
#include "dialects/gold/compile.h"
#include "drive/axis.h"
#include "gold_drive.h"
#include "support/files.h"

namespace uprog::controller {
namespace {

std::string one(Controller& c, const std::string& line) {
  const std::vector<Answer> a = c.send(line);
  if (a.size() != 1) return "<" + std::to_string(a.size()) + " answers>";
  return a[0].is_error() ? "!" + std::to_string(a[0].error) : a[0].text;
}

std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("uprog_controller_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

TEST(controller, AcceptanceMove) {
  Controller c(gold_options());
  for (const char* line : {"UM=5", "PX=0", "MO=1"}) ASSERT_TRUE(c.send(line).empty()) << line;
  c.advance(20000);
  for (const char* line : {"PA=100000", "SP=50000", "AC=1000000", "DC=1000000"})
    ASSERT_TRUE(c.send(line).empty());
  const uint64_t t0 = c.now_us();
  ASSERT_TRUE(c.send("BG").empty());
  c.advance(1000000 - (c.now_us() - t0));
  const double px_1s = c.axis().position();
  EXPECT_NEAR(px_1s, 48750.0, 487.5);
  // Settled: within +-1 from some moment on, which must be within 5 ms of 2.05 s.
  uint64_t settled_at = 0;
  while (c.now_us() - t0 < 2200000) {
    c.advance(50);
    const int32_t px = c.axis().position();
    if (std::abs(px - 100000) <= 1) {
      if (settled_at == 0) settled_at = c.now_us() - t0;
    } else {
      settled_at = 0;
    }
  }
  ASSERT_NE(settled_at, 0u);
  EXPECT_LE(settled_at, 2055000u);
  std::printf("acceptance: PX(1.0 s) = %.0f, settled within +-1 at %.3f ms after BG\n", px_1s,
              static_cast<double>(settled_at) / 1000.0);
}

TEST(controller, GarbageAndHugeLinesAreRefusedWithoutHarm) {
  Controller c(gold_options());
  ASSERT_TRUE(c.download(compile_bytes("int v\nfunction main()\nv = 5\nreturn\n")).ok);
  ASSERT_TRUE(load(c));
  EXPECT_EQ(one(c, "v=3"), "<0 answers>");
  EXPECT_EQ(one(c, "@#$%^&*("), "!19");
  EXPECT_EQ(one(c, std::string(100000, 'x')), "!19");
  EXPECT_EQ(one(c, std::string(511, ' ') + "1"), "1");  // blanks are trimmed before the limit
  EXPECT_EQ(one(c, "EC"), "19");
  EXPECT_EQ(one(c, "XQ##"), "!202");
  EXPECT_EQ(one(c, "DB##RV[9]=v"), "!3");
  EXPECT_EQ(one(c, "DB##RV[1]=nothere"), "!209");
  EXPECT_EQ(one(c, "DB##RV[1]=v"), "<0 answers>");
  EXPECT_EQ(one(c, "while(1)"), "!19");
  EXPECT_EQ(one(c, "v"), "3");
  EXPECT_EQ(ps(c), -1);
}

// The image names the dialect whose compiler made it: a Gold drive takes Gold's and hand-made
// ones, and refuses another dialect's, at download and at boot, keeping what it had.
TEST(controller, AnotherDialectsProgramIsRefused) {
  const std::string dir = temp_dir("foreign");
  SourceFile source{"test.ehl", "int v\nfunction main()\nv = 5\nreturn\n"};
  gold::CompileResult compiled = gold::compile(source);
  ASSERT_TRUE(compiled.ok());
  ASSERT_EQ(compiled.image.dialect, "gold");
  bytecode::Image foreign = compiled.image;
  foreign.dialect = "pdl";
  const std::vector<uint8_t> foreign_bytes = bytecode::encode(foreign);
  {
    ControllerOptions o = gold_options();
    o.state_dir = dir;
    Controller c(o);
    ASSERT_TRUE(c.download(bytecode::encode(compiled.image)).ok);
    const DownloadResult r = c.download(foreign_bytes);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error, "the program is for the pdl dialect; this drive runs gold");
    EXPECT_EQ(read_binary_file(dir + "/program.upi"), bytecode::encode(compiled.image));
    bytecode::Image hand_made = compiled.image;
    hand_made.dialect.clear();
    EXPECT_TRUE(c.download(bytecode::encode(hand_made)).ok);
  }
  ASSERT_TRUE(
      write_file_atomically(dir + "/program.upi", foreign_bytes.data(), foreign_bytes.size()));
  ControllerOptions o = gold_options();
  o.state_dir = dir;
  Controller c(o);
  ASSERT_EQ(c.boot_messages().size(), 1u);
  EXPECT_NE(c.boot_messages()[0].find("the program is for the pdl dialect"), std::string::npos)
      << c.boot_messages()[0];
  EXPECT_EQ(ps(c), -2);
}

TEST(controller, ADriveRefusalSaysWhatWentWrong) {
  Controller c(gold_options());
  const std::vector<Answer> a = c.send("AC=-5");  // AC takes positive values only
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].error, 21);
  EXPECT_EQ(a[0].text, "Value out of the command's range");
  EXPECT_EQ(one(c, "EC"), "21");
}

TEST(controller, RefusedDownloadKeepsThePreviousProgram) {
  const std::string dir = temp_dir("refused");
  const std::vector<uint8_t> good = compile_bytes("int v\nfunction main()\nv = 5\nreturn\n");
  {
    ControllerOptions o = gold_options();
    o.state_dir = dir;
    Controller c(o);
    ASSERT_TRUE(c.download(good).ok);
    std::vector<uint8_t> bad = good;
    bad[bad.size() / 2] ^= 0x55;  // breaks the CRC
    const DownloadResult r = c.download(bad);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("CRC"), std::string::npos) << r.error;
    EXPECT_FALSE(c.download({1, 2, 3}).ok);
    ASSERT_EQ(one(c, "CC"), "<0 answers>");
    EXPECT_EQ(one(c, "XQ##main"), "<0 answers>");
    c.advance(10000);
    EXPECT_EQ(one(c, "v"), "5");
  }
  auto stored = read_binary_file(dir + "/program.upi");
  ASSERT_TRUE(stored);
  EXPECT_EQ(*stored, good);
}

TEST(controller, StoredProgramAndParametersSurviveABoot) {
  const std::string dir = temp_dir("persist");
  ControllerOptions o = gold_options();
  o.state_dir = dir;
  {
    Controller c(o);
    ASSERT_TRUE(c.download(compile_bytes("int v\n#@AUTOEXEC\nv = 42\nreturn\n")).ok);
    EXPECT_EQ(one(c, "UI[3]=77"), "<0 answers>");
    EXPECT_EQ(one(c, "SV"), "<0 answers>");
  }
  {
    Controller c(o);
    EXPECT_TRUE(c.boot_messages().empty());
    c.advance(10000);
    EXPECT_EQ(one(c, "v"), "42");  // AUTOEXEC ran at power-up
    EXPECT_EQ(one(c, "UI[3]"), "77");
  }
  o.safe_boot = true;
  {
    Controller c(o);
    c.advance(10000);
    EXPECT_EQ(one(c, "v"), "0");  // safe boot skips AUTOEXEC
    EXPECT_EQ(ps(c), -1);
  }
}

TEST(controller, CorruptStoredImageIsRefusedAtBoot) {
  const std::string dir = temp_dir("corrupt");
  std::filesystem::create_directories(dir);
  const std::string junk = "UPRG this is not an image";
  ASSERT_TRUE(write_file_atomically(dir + "/program.upi", junk.data(), junk.size()));
  ControllerOptions o = gold_options();
  o.state_dir = dir;
  Controller c(o);
  ASSERT_EQ(c.boot_messages().size(), 1u);
  EXPECT_NE(c.boot_messages()[0].find("refused"), std::string::npos);
  EXPECT_EQ(ps(c), -2);
  EXPECT_EQ(one(c, "3+4"), "7");
  EXPECT_EQ(one(c, "CC"), "!207");
}

TEST(controller, UnlimitedBudgetRunsUntilAWait) {
  ControllerOptions o = gold_options();
  o.timing.unlimited = true;
  o.timing.background_us = 50;  // a background pass per servo cycle: one slice per advance(50)
  Controller c(o);
  ASSERT_TRUE(c.download(compile_bytes("int i, done\nfunction main()\nfor i = 1:1000\nend\ndone = "
                                       "1\nwait(100)\ndone = 2\nreturn\n"))
                  .ok);
  ASSERT_TRUE(load(c));
  ASSERT_EQ(xq(c, "main"), 0);
  c.advance(50);
  EXPECT_EQ(one(c, "done"), "1");  // 1000 loop lines ran within one cycle
  c.advance(100000);
  EXPECT_EQ(one(c, "done"), "2");
}

// A busy loop under the unlimited budget is cut at the line cap each cycle: the drive still
// answers, and every cycle runs the same number of lines.
TEST(controller, UnlimitedBudgetCapsABusyLoopPerCycle) {
  ControllerOptions o = gold_options();
  o.timing.unlimited = true;
  o.timing.unlimited_line_cap = 3000;
  o.timing.background_us = 50;  // a background pass per servo cycle: one slice per advance(50)
  Controller c(o);
  ASSERT_TRUE(
      c.download(compile_bytes("int i\nfunction main()\nwhile (1)\ni = i + 1\nend\nreturn\n")).ok);
  ASSERT_TRUE(load(c));
  ASSERT_EQ(xq(c, "main"), 0);
  // Each iteration ends three lines: the while header, `i = i + 1`, and the loop's end.
  c.advance(50);
  EXPECT_EQ(one(c, "i"), "1000");
  // The command line's expression took a cycle of its own (its slice ran after the answer).
  c.advance(50);
  EXPECT_EQ(one(c, "i"), "3000");
}

// A hand-made image whose loop never ends a line: the drive goes on answering, cycle after
// cycle, while the program spins (at most Timing::back_jump_cap jumps per slice).
TEST(controller, ALoopWithoutALineEndDoesNotHangTheDrive) {
  bytecode::Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(
      bytecode::assemble(".global int \"n\" 1\n"
                         ".routine function \"main\" in=0 out=0 entry=main\n"
                         "main:\n  LDG n\n  PUSHI 1\n  ADDI\n  STG n\n  JMP main\n",
                         "spin.s", image, errors));
  ControllerOptions o = gold_options();
  o.timing.back_jump_cap = 5000;
  o.timing.background_us = 50;  // a background pass per servo cycle: one slice per advance(50)
  Controller c(o);
  ASSERT_TRUE(c.download(bytecode::encode(image)).ok);
  ASSERT_TRUE(load(c));
  ASSERT_EQ(xq(c, "main"), 0);
  c.advance(50);
  EXPECT_EQ(one(c, "n"), "5000");
  EXPECT_EQ(one(c, "3+4"), "7");
  EXPECT_EQ(one(c, "n"), "15000");  // each command line took a cycle of its own
}

}  // namespace
}  // namespace uprog::controller
