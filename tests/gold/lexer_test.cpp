// The lexer and parser never crash or hang: hostile inputs, deep nesting, long lines, and the
// comment and continuation forms of manual 1.1, 1.14 and 2.7.2 (error 64).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "dialects/gold/compile.h"
#include "gold_runner.h"

namespace uprog::gold_test {
namespace {

gold::CompileResult compile(const std::string& text) {
  return gold::compile(SourceFile{"t.ehl", text});
}

TEST(gold_lexer, CommentsAndContinuation) {
  const auto r = compile(
      "/* a block\n   comment */\nint a // line comment\n** interpreter comment\n##S\n"
      "a = 1 + ...   continued\n  2;\n");
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
}

TEST(gold_lexer, SemicolonsAnywhere) {
  const auto r = compile("int MS_\n##S;\nBG;\nuntil (MS != 2);\nwait(1);\nreturn;\n");
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
}

TEST(gold_lexer, KeywordsIgnoreCaseVariablesDoNot) {
  auto r = compile("function main()\nint A\nIF A\nA = 1\nEnd\nReturn\n");
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
  r = compile("function main()\nint A\na = 1\nreturn\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].code, 12);
}

TEST(gold_lexer, DeepNestingIsBounded) {
  std::string deep = "##S\nPA = " + std::string(5000, '(') + "1" + std::string(5000, ')') + "\n";
  auto r = compile(deep);
  ASSERT_FALSE(r.ok());
  bool stack_full = false;
  for (const Diagnostic& d : r.diagnostics) stack_full = stack_full || d.code == 3;
  EXPECT_TRUE(stack_full) << format_text(r.diagnostics);
  std::string minus = "##S\nPA = " + std::string(100000, '-') + "1\n";
  r = compile(minus);
  EXPECT_FALSE(r.ok());
  std::string blocks = "##S\n";
  for (int i = 0; i < 5000; ++i) blocks += "if 1\n";
  r = compile(blocks);
  EXPECT_FALSE(r.ok());
}

// Random text never crashes the compiler, and whatever it says is well formed: a program that
// compiles gives an image the VM's verifier accepts; one that does not gets at least one error,
// each with a code of the manual's table and a place inside the text.
TEST(gold_lexer, RandomInputGetsAnImageOrPlacedErrors) {
  std::mt19937 rng(12345);
  const std::string alphabet =
      "ab01.x#@[](),;:=+-*/%<>!&|~^ \n\tfunction if end while for return case switch try catch ...";
  size_t error_count = 0;
  for (int n = 0; n < 300; ++n) {
    std::string s;
    const size_t len = rng() % 400;
    for (size_t i = 0; i < len; ++i) s += alphabet[rng() % alphabet.size()];
    SCOPED_TRACE(s);
    const gold::CompileResult r = compile(s);
    if (r.ok()) {
      GoldRun run;
      EXPECT_TRUE(run.load(r.image));
      continue;
    }
    ASSERT_FALSE(r.diagnostics.empty());
    const auto lines = static_cast<int>(std::count(s.begin(), s.end(), '\n') + 1);
    for (const Diagnostic& d : r.diagnostics) {
      ++error_count;
      EXPECT_EQ(d.scheme, "gold") << format_text(d);
      EXPECT_TRUE(d.code >= 1 && d.code <= 97) << format_text(d);
      EXPECT_FALSE(d.message.empty());
      EXPECT_TRUE(d.where.line >= 1 && d.where.line <= lines) << format_text(d);
    }
  }
  EXPECT_GT(error_count, 0u);
}

}  // namespace
}  // namespace uprog::gold_test
