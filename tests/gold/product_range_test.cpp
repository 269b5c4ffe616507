// Gold's promoting multiply (manual 1.5) where the compiler proves the product fits: plain MULI,
// the same results; and the cases it cannot prove, which keep the promoting MULID.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "bytecode/assembly.h"
#include "gold_runner.h"

namespace uprog::gold_test {
namespace {

// How many times the unoptimised code uses `op` (the peephole pass may fuse it away).
int count_op(const std::string& source, const std::string& op) {
  gold::CompileOptions o;
  o.optimize = false;
  const gold::CompileResult r = gold::compile(SourceFile{"t.ehl", source}, o);
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
  const std::string text = bytecode::disassemble(r.image);
  const std::regex word("\\b" + op + "\\b");
  return static_cast<int>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), word), std::sregex_iterator()));
}

TEST(gold_product_range, LoopVariableTimesConstantIsAnIntProduct) {
  const std::string src = R"(
int a[2040]
function main()
global int a[2040]
int r, i
for r = 1:3
  for i = 0:2039
    a[i] = (i * 7919 + r) % 2040
  end
end
return
)";
  EXPECT_EQ(count_op(src, "MULID"), 0);
  EXPECT_EQ(count_op(src, "MULI"), 1);
  EXPECT_EQ(count_op(src, "D2IT"), 0);
  GoldRun p;
  ASSERT_TRUE(p.compile(src));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  for (int i : {0, 1, 7, 2039})
    EXPECT_EQ(p.i("a", static_cast<uint32_t>(i)), (i * 7919 + 3) % 2040) << i;
}

TEST(gold_product_range, RemainderMaskAndNegativeStepBoundTheProduct) {
  const std::string src = R"(
int s
function main()
int k
s = 0
for k = 100000:-3:1
  s = s + (k % 1000) * (k & 1023) + (k * -20000) % 7
end
return
)";
  EXPECT_EQ(count_op(src, "MULID"), 0);
  GoldRun p;
  ASSERT_TRUE(p.compile(src));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  int32_t want = 0;
  for (int64_t k = 100000; k >= 1; k -= 3)
    want = static_cast<int32_t>(static_cast<uint32_t>(want) +
                                static_cast<uint32_t>((k % 1000) * (k & 1023) + (k * -20000) % 7));
  EXPECT_EQ(p.i("s"), want);
}

TEST(gold_product_range, AProductThatMayOverflowStillPromotes) {
  const std::string src = R"(
float y, z
int n
function main()
int i, j
y = 100000*100000        // 1.0e10, a float (1.5)
for i = 1:100000
  z = i * 100000         // 1.0e10 at the end: the bounds do not prove it fits
end
for j = 0:10
  j = j + 100000         // assigned in the body: its range is unknown
  n = j * 3
end
return
)";
  EXPECT_EQ(count_op(src, "MULI"), 0);
  EXPECT_EQ(count_op(src, "MULID"), 3);
  GoldRun p;
  ASSERT_TRUE(p.compile(src));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_FLOAT_EQ(p.f("y"), 1.0e10f);
  EXPECT_FLOAT_EQ(p.f("z"), 1.0e10f);
  EXPECT_EQ(p.i("n"), 300000);
}

TEST(gold_product_range, AGlobalLoopVariableIsNotTrusted) {
  // A called function (or an auto-routine) may change a global, so its range is never known.
  const std::string src = R"(
int g, t
function bump()
g = 70000
return
function main()
for g = 1:10
  bump()
  t = g * 70000          // 4.9e9: must become a float
end
return
)";
  EXPECT_EQ(count_op(src, "MULI"), 0);
  GoldRun p;
  ASSERT_TRUE(p.compile(src));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("t"), 2147483647);  // the float product saturates into the int
}

}  // namespace
}  // namespace uprog::gold_test
