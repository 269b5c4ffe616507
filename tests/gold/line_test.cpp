// The command line (manual 1.1): a host line compiled into a tiny image and run; shown values
// keep their run-time type; a loaded program's globals are known by name.
#include <gtest/gtest.h>

#include "gold_runner.h"

namespace uprog::gold_test {
namespace {

struct Shown {
  bool is_float;
  int32_t i;
  float f;
};

std::vector<Shown> run_line(const std::string& line, GoldRun& p,
                            const std::vector<gold::KnownGlobal>& known = {}) {
  gold::CompiledLine c = gold::compile_line(line, known);
  EXPECT_TRUE(c.ok()) << format_text(c.diagnostics);
  if (!c.ok()) return {};
  std::vector<gold::LineValue> values = c.values;
  if (!p.load(std::move(c.image))) return {};
  EXPECT_EQ(p.run("$line"), vm::SliceEnd::Finished);
  std::vector<Shown> out;
  for (const gold::LineValue& v : values) {
    Value x;
    p.machine.read_global(v.value_global, 0, x);
    bool is_float = v.kind == gold::Kind::Float;
    if (v.kind == gold::Kind::Dynamic) {
      Value tag;
      p.machine.read_global(static_cast<uint32_t>(v.tag_global), 0, tag);
      is_float = tag.i != 0;
    }
    out.push_back({is_float, x.i, x.f});
  }
  return out;
}

TEST(gold_line, ManualExamples) {
  GoldRun p;
  auto r = run_line("3+4", p);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].is_float);
  EXPECT_EQ(r[0].i, 7);

  GoldRun p2;
  r = run_line("PX=7; PX-3", p2);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].i, 4);

  GoldRun p3;
  r = run_line("(3.2+4)/2", p3);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].is_float);
  EXPECT_FLOAT_EQ(r[0].f, 3.6f);
}

TEST(gold_line, ProductKeepsItsRunTimeType) {
  GoldRun p;
  auto r = run_line("100000*100000; 5*4; 2147483648", p);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_TRUE(r[0].is_float);
  EXPECT_FLOAT_EQ(r[0].f, 1e10f);
  EXPECT_FALSE(r[1].is_float);
  EXPECT_EQ(r[1].i, 20);
  EXPECT_TRUE(r[2].is_float);  // beyond the int range: a float (1.3)
}

TEST(gold_line, KnownGlobalsOfALoadedProgram) {
  const gold::CompileResult prog =
      gold::compile(SourceFile{"p.ehl", "int myvar, arr[3]\nfloat temp\n##A\nmyvar = 1\n"});
  ASSERT_TRUE(prog.ok()) << format_text(prog.diagnostics);
  const auto known = gold::known_globals(prog.image);
  ASSERT_EQ(known.size(), 3u);
  GoldRun p;
  auto r = run_line("myvar=5; arr[2]=myvar*2; temp=12345678; arr[2]; temp", p, known);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].i, 10);
  EXPECT_TRUE(r[1].is_float);
  EXPECT_FLOAT_EQ(r[1].f, 12345678.0f);
  EXPECT_EQ(p.i("myvar"), 5);
}

TEST(gold_line, ErrorsAreReported) {
  EXPECT_FALSE(gold::compile_line("nosuch + 1").ok());
  EXPECT_FALSE(gold::compile_line("BG=10").ok());
  EXPECT_FALSE(gold::compile_line("3 +").ok());
  EXPECT_TRUE(gold::compile_line("BG").ok());
}

}  // namespace
}  // namespace uprog::gold_test
