// One hand-made bad image for each verifier rule (tests/bytecode/bad/*.s, each naming the error
// it expects), a check that every rule has one, and random code whose accepted images must run
// safely on the VM.
#include "bytecode/verifier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "bytecode/opcodes.h"
#include "run_image.h"
#include "vm/machine.h"

namespace uprog::bytecode {
namespace {

namespace fs = std::filesystem;

const char* const kErrorNames[] = {
    "Ok",          "EmptyCode",        "BadOpcode",      "Truncated",     "BreakInImage",
    "BadConstant", "BadGlobal",        "BadLocal",       "BadRoutine",    "BadTarget",
    "BadOperand",  "BadEntry",         "StackUnderflow", "StackOverflow", "StackMismatch",
    "FallsOffEnd", "ReturnWithValues", "NoScratch",      "BadLineEnd"};

VerifyResult verify_bytes(const std::vector<uint8_t>& bytes) {
  ImageView view;
  EXPECT_EQ(load_image(bytes.data(), bytes.size(), view), LoadError::Ok);
  std::vector<uint32_t> scratch(verify_scratch_size(view) / 4 + 1);
  return verify(view, VerifyLimits{}, scratch.data(), scratch.size() * 4);
}

// Runs routine 0 of verified image bytes on a fresh Machine for at most 64 slices of 1000
// instructions; how its last slice ended.
vm::SliceEnd run_once(const std::vector<uint8_t>& bytes) {
  ImageView view;
  EXPECT_EQ(load_image(bytes.data(), bytes.size(), view), LoadError::Ok);
  std::vector<uint64_t> memory(vm::Machine::memory_needed(view, {}) / 8 + 1);
  fuzz::FuzzHost host;
  vm::Machine machine;
  EXPECT_TRUE(
      machine.load(bytes.data(), bytes.size(), {}, memory.data(), memory.size() * 8, host).ok());
  EXPECT_EQ(machine.start(0, 0), vm::RunError::None);
  vm::SliceEnd end = vm::SliceEnd::NotRunning;
  for (int slice = 0; slice < 64; ++slice) {
    end = machine.run_slice(0, vm::Budget::of_instructions(1000)).end;
    if (end == vm::SliceEnd::Finished || end == vm::SliceEnd::Error) break;
  }
  return end;
}

std::vector<fs::path> bad_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(UPROG_SOURCE_DIR) / "tests/bytecode/bad"))
    files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

class BadImage : public ::testing::TestWithParam<fs::path> {};

TEST_P(BadImage, IsRefusedForItsReason) {
  std::ifstream in(GetParam());
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string s = text.str();
  ASSERT_TRUE(std::regex_search(s, m, std::regex(R"(; expect verify: (\w+))")));
  Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(assemble(s, GetParam().string(), image, errors)) << format_text(errors);
  const VerifyResult r = verify_bytes(encode(image));
  EXPECT_STREQ(kErrorNames[static_cast<int>(r.error)], m[1].str().c_str())
      << verify_error_text(r.error);
}

INSTANTIATE_TEST_SUITE_P(Files, BadImage, ::testing::ValuesIn(bad_files()),
                         [](const auto& param_info) { return param_info.param.stem().string(); });

TEST(Verifier, EveryRuleHasABadImage) {
  std::set<std::string> covered;
  for (const auto& f : bad_files()) {
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    std::smatch m;
    const std::string s = text.str();
    if (std::regex_search(s, m, std::regex(R"(; expect verify: (\w+))"))) covered.insert(m[1]);
  }
  for (const char* name : kErrorNames) {
    const std::string n = name;
    if (n == "Ok" || n == "NoScratch") continue;  // NoScratch is the caller's fault, tested below
    EXPECT_TRUE(covered.count(n)) << "no bad image in tests/bytecode/bad for " << n;
  }
}

TEST(Verifier, RefusesTooLittleScratch) {
  Image image;
  image.code = {make_word(Op::RET, 0)};
  image.routines = {{"main", RoutineKind::Function, 0, 0, {}, 0}};
  const auto bytes = encode(image);
  ImageView view;
  ASSERT_EQ(load_image(bytes.data(), bytes.size(), view), LoadError::Ok);
  uint32_t scratch[1];
  EXPECT_EQ(verify(view, {}, scratch, sizeof scratch).error, VerifyError::NoScratch);
}

TEST(Verifier, ReportsTheDeepestStack) {
  Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(
      assemble(".routine function \"m\" in=0 out=0 entry=m\nm:\n PUSHI 1\n PUSHI 2\n "
               "PUSHI 3\n ADDI\n ADDI\n POP\n RET\n",
               "t", image, errors));
  const VerifyResult r = verify_bytes(encode(image));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.max_depth, 3u);
}

// The depth on entry to each instruction on one routine's paths: what a debugger that moves a
// thread's pc must keep; none for an instruction that only another routine reaches.
TEST(Verifier, StackDepthAtFollowsOneRoutinesPaths) {
  Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(
      assemble(".routine function \"m\" in=0 out=0 entry=m\n"
               ".routine function \"f\" in=0 out=0 entry=f\n"
               "m:\n PUSHI 1\n PUSHI 2\n ADDI\n POP\n RET\n"
               "f:\n RET\n",
               "t", image, errors));
  const auto bytes = encode(image);
  ImageView view;
  ASSERT_EQ(load_image(bytes.data(), bytes.size(), view), LoadError::Ok);
  std::vector<uint32_t> scratch(verify_scratch_size(view) / 4 + 1);
  const size_t size = scratch.size() * 4;
  // m's code words: PUSHI 1 (0), PUSHI 2 (1), ADDI (2), POP (3), RET (4); f's RET (5).
  const uint32_t expected[] = {0, 1, 2, 1, 0};
  for (uint32_t pc = 0; pc < 5; ++pc) {
    uint32_t depth = 99;
    ASSERT_TRUE(stack_depth_at(view, {}, 0, pc, scratch.data(), size, depth)) << pc;
    EXPECT_EQ(depth, expected[pc]) << pc;
  }
  uint32_t depth = 0;
  EXPECT_FALSE(stack_depth_at(view, {}, 0, 5, scratch.data(), size, depth));  // f's
  EXPECT_TRUE(stack_depth_at(view, {}, 1, 5, scratch.data(), size, depth));
  EXPECT_FALSE(stack_depth_at(view, {}, 0, 6, scratch.data(), size, depth));  // past the end
  EXPECT_FALSE(stack_depth_at(view, {}, 2, 0, scratch.data(), size, depth));  // no such routine
  EXPECT_FALSE(stack_depth_at(view, {}, 0, 0, scratch.data(), 4, depth));     // too little scratch
}

// Random code words with valid tables: the verifier must never crash, and what it accepts must
// be what it promises: the image decodes to the same code, the Machine's own load accepts it,
// and it runs (every routine, with an event, a halt and a breakpoint: fuzz/run_image.h) within a
// bounded budget without a crash or undefined behaviour (scripts/test-sanitizers runs this too).
TEST(Verifier, WhatItAcceptsRunsSafely) {
  uint32_t seed = 99;
  // The high bits of the LCG: its low bits repeat with short periods, so that `% n` of the whole
  // word would reach only some opcode and operand pairs (and which ones, changes with n).
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 12;
  };
  int accepted = 0;
  int accepted_with_marks = 0;
  std::map<vm::SliceEnd, int> ends;
  for (int round = 0; round < 80000; ++round) {
    Image image;
    image.constants = {{ValueType::Int, 1}};
    image.globals = {{"g", ValueType::Int, 4}};
    image.routines = {
        {"m", RoutineKind::Function, 0, 1, {{"a", ValueType::Int}, {"b", ValueType::Int}}, 0}};
    const uint32_t n = 1 + next() % 12;
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t op = next() % (kOpCount + 2);
      const uint32_t a = next() % 6;
      const uint32_t line_end = next() % 8 == 0 ? kLineEndBit : 0u;  // some marked, some refused
      image.code.push_back(op | line_end | a_field(a));
    }
    const std::vector<uint8_t> bytes = encode(image);
    if (!verify_bytes(bytes).ok()) continue;
    ++accepted;
    accepted_with_marks +=
        std::any_of(image.code.begin(), image.code.end(), word_ends_line) ? 1 : 0;
    SCOPED_TRACE(disassemble(image));
    Image decoded;
    std::string why;
    ASSERT_TRUE(decode(bytes.data(), bytes.size(), decoded, why)) << why;
    EXPECT_EQ(decoded.code, image.code);
    EXPECT_TRUE(fuzz::load_and_run(bytes.data(), bytes.size()).ok())
        << "verified, but the Machine refuses it";
    ends[run_once(bytes)]++;
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(accepted_with_marks, 10);
  // The random programs reach the ends a real one does, so the runs above exercised the VM.
  EXPECT_GT(ends[vm::SliceEnd::Finished], 0);
  EXPECT_GT(ends[vm::SliceEnd::Error], 0);
}

}  // namespace
}  // namespace uprog::bytecode
