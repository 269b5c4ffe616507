// Hostile input: the preprocessor must finish, keep one output line per input line, and
// never crash, whatever it is given (DESIGN.md: bad input gets a clear error, never a crash).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "preproc/preprocess.h"

namespace uprog::preproc {
namespace {

Preprocessed run(const std::string& text, DiagnosticList& d) {
  return preprocess({"g.prg", text}, PreprocOptions{}, d);
}

size_t lines(const std::string& s) {
  return static_cast<size_t>(std::count(s.begin(), s.end(), '\n'));
}

TEST(preproc_robustness, RandomBytesAndRandomDirectives) {
  std::mt19937 rng(12345);
  const std::string pieces[] = {
      "#define ", "#if ", "#elseif ", "#else", "#endif", "#undef ", "#ifdef ", "A",
      "B ",       "1",    "/*",       "*/",    "//",     "**",      "\"",      "\n",
      "(",        ")",    "-",        "0x",    "1e",     ".",       "\r\n",    std::string(1, '\0'),
      "\xff",     "##",   "#@"};
  for (int round = 0; round < 300; ++round) {
    std::string src;
    const int n = static_cast<int>(rng() % 400);
    for (int i = 0; i < n; ++i) {
      if (rng() % 3 == 0)
        src += static_cast<char>(rng() % 256);
      else
        src += pieces[rng() % std::size(pieces)];
    }
    DiagnosticList d;
    const Preprocessed p = run(src, d);
    ASSERT_EQ(lines(p.text), lines(src)) << "round " << round;
    for (size_t i = 0; i <= p.text.size(); i += 7) {
      const Location l = p.map.locate(i);
      ASSERT_GE(l.line, 1);
      ASSERT_LE(static_cast<size_t>(l.line), lines(src) + 1);
    }
  }
}

TEST(preproc_robustness, HugeLine) {
  std::string src =
      "#define X 1\n" + std::string(1 << 22, 'a') + " X " + std::string(1 << 20, '(') + "\n";
  DiagnosticList d;
  const Preprocessed p = run(src, d);
  EXPECT_EQ(p.text.size(), src.size() - 11);
  EXPECT_EQ(p.map.locate(p.text.size() - 2).column, static_cast<int>((1 << 22) + 3 + (1 << 20)));
}

TEST(preproc_robustness, DeepNesting) {
  std::string src;
  for (int i = 0; i < 100000; ++i) src += "#if 1\n";
  src += "x\n";
  for (int i = 0; i < 100000; ++i) src += "#endif\n";
  DiagnosticList d;
  const Preprocessed p = run(src, d);
  EXPECT_FALSE(d.has_errors());
  EXPECT_NE(p.text.find('x'), std::string::npos);
}

TEST(preproc_robustness, DeepConditionIsAnErrorNotACrash) {
  DiagnosticList d;
  run("#if " + std::string(200000, '(') + "1\n#endif\n", d);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].code, 94);
}

TEST(preproc_robustness, LongChainOfDefinesHitsTheDepthBound) {
  // M0 -> M1 -> ... -> M79: each a string, so the expansion nests 80 deep (limit 64).
  std::string src;
  for (int i = 0; i < 80; ++i)
    src += "#define M" + std::to_string(i) + " x+M" + std::to_string(i + 1) + "\n";
  src += "y = M0\ny = M60\n";
  DiagnosticList d;
  const Preprocessed p = run(src, d);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].code, 39);  // Gold: Code is too complex
  EXPECT_EQ(d.items()[0].where.line, 81);
  EXPECT_NE(p.text.find("y = M0\n"), std::string::npos);  // left as written
  EXPECT_NE(p.text.find("y = x+x+"), std::string::npos);  // M60 is 20 deep: expanded
}

TEST(preproc_robustness, ExponentialDefinesAreBounded) {
  // Each name doubles the previous one: 2^60 characters if nothing stopped it.
  std::string src = "#define E0 ab\n";
  for (int i = 1; i <= 60; ++i)
    src += "#define E" + std::to_string(i) + " E" + std::to_string(i - 1) + " E" +
           std::to_string(i - 1) + "\n";
  for (int i = 0; i < 2000; ++i) src += "E60 E10\n";
  DiagnosticList d(100000);
  const Preprocessed p = run(src, d);
  EXPECT_TRUE(d.has_errors());
  EXPECT_EQ(d.items()[0].code, 39);
  EXPECT_LT(p.text.size(), size_t{64} << 20);
  EXPECT_EQ(lines(p.text), lines(src));
}

TEST(preproc_robustness, MutualRecursionEnds) {
  DiagnosticList d;
  const Preprocessed p = run("#define A B\n#define B A\nA B\n", d);
  EXPECT_EQ(p.text, "\n\nA B\n");
  EXPECT_FALSE(d.has_errors());
}

TEST(preproc_robustness, NoFinalNewlineAndOnlyNewlines) {
  DiagnosticList d;
  EXPECT_EQ(run("#define A 1\nA", d).text, "\n1");
  EXPECT_EQ(run("\n\n\n", d).text, "\n\n\n");
  EXPECT_EQ(run("#if 1", d).text, "");
  EXPECT_EQ(d.items().size(), 1u);  // the #if left open
}

}  // namespace
}  // namespace uprog::preproc
