// Differential test through the Gold command line: random expressions compiled by
// gold::compile_line, run on the VM, and compared with the reference (type and value).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "dialects/gold/compile.h"
#include "expr_tree.h"
#include "gold_text.h"
#include "vm_runner.h"

namespace uprog::differential {
namespace {

uint32_t cases_per_run(uint32_t fallback) {
  const char* n = std::getenv("UPROG_DIFF_CASES");
  return n != nullptr ? static_cast<uint32_t>(std::strtoul(n, nullptr, 10)) : fallback;
}
uint32_t base_seed() {
  const char* s = std::getenv("UPROG_DIFF_SEED");
  return s != nullptr ? static_cast<uint32_t>(std::strtoul(s, nullptr, 10)) : 20240601u;
}

std::vector<gold::KnownGlobal> program_globals() {
  std::string source = "int i0, i1, i2, i3\nfloat f0, f1, f2, f3\n##A\ni0 = 1\n";
  const gold::CompileResult program = gold::compile(SourceFile{"vars.ehl", source});
  EXPECT_TRUE(program.ok()) << format_text(program.diagnostics);
  return gold::known_globals(program.image);
}

TEST(DifferentialGoldLine, RandomExpressionsMatchTheReference) {
  const std::vector<gold::KnownGlobal> known = program_globals();
  ASSERT_EQ(known.size(), 8u);
  const uint32_t cases = cases_per_run(4000);
  Generator gen(base_seed());
  uint32_t ran = 0, errors_expected = 0, floats = 0, failures = 0;
  for (uint32_t n = 0; n < cases; ++n) {
    const Vars vars = gen.vars();
    const auto expr = gen.expression(1 + static_cast<int>(gen.below(5)));
    Outcome want = evaluate(*expr, vars, IntMul::Promote);
    // A quarter of the cases assign the result to a variable and show the variable (1.10).
    const uint32_t assign = gen.below(8);
    std::string line = gold_assignments(vars);
    const std::string text = gold_text(*expr, n * 2654435761u + 1);
    if (assign == 0) {
      line += "i2=" + text + "; i2";
      if (!want.division_by_zero && want.value.is_float)
        want.value = Num::of_int(ref::round_to_int(want.value.f));
    } else if (assign == 1) {
      line += "f2=" + text + "; f2";
      if (!want.division_by_zero) want.value = Num::of_float(ref::to_float(want.value));
    } else {
      line += text;
    }
    const gold::CompiledLine compiled = gold::compile_line(line, known);
    std::string got;
    bool ok = false;
    if (!compiled.ok()) {
      // A division by a constant zero may be refused at compile time ("Division by zero", 86).
      for (const Diagnostic& d : compiled.diagnostics)
        ok = want.division_by_zero && compiled.diagnostics.size() == 1 && d.code == 86;
      got = "compile error: " + format_text(compiled.diagnostics);
    } else {
      VmRun run;
      run.run(compiled.image);
      ++ran;
      if (!run.loaded) {
        got = "the VM refused the line's image";
      } else if (want.division_by_zero) {
        ok = run.end == vm::SliceEnd::Error && run.error == vm::RunError::DivisionByZero;
        got = "end " + std::to_string(static_cast<int>(run.end)) + ", error " +
              std::to_string(static_cast<int>(run.error));
      } else if (run.end != vm::SliceEnd::Finished || compiled.values.size() != 1) {
        got = "end " + std::to_string(static_cast<int>(run.end)) + ", error " +
              std::to_string(static_cast<int>(run.error)) + ", values " +
              std::to_string(compiled.values.size());
      } else {
        const gold::LineValue& v = compiled.values[0];
        const Value x = run.global(v.value_global);
        bool is_float = v.kind == gold::Kind::Float;
        if (v.kind == gold::Kind::Dynamic)
          is_float = run.global(static_cast<uint32_t>(v.tag_global)).i != 0;
        const Num shown = is_float ? Num::of_float(x.f) : Num::of_int(x.i);
        ok = same(shown, want.value);
        got = describe(shown);
      }
    }
    errors_expected += want.division_by_zero;
    floats += !want.division_by_zero && want.value.is_float;
    if (!ok && ++failures <= 25) {
      ADD_FAILURE() << "case " << n << " (seed " << base_seed() << "): " << line
                    << "\n  reference: "
                    << (want.division_by_zero ? "division by zero" : describe(want.value))
                    << "\n  VM:        " << got;
    }
  }
  EXPECT_EQ(failures, 0u) << "of " << cases << " cases";
  // The test must exercise what it claims: most lines compile and run, some fail at run time,
  // some give floats.
  EXPECT_GT(ran, cases * 9 / 10);
  EXPECT_GT(errors_expected, 0u);
  EXPECT_GT(floats, cases / 10);
  std::printf(
      "[ differential ] gold line: %u cases, %u run on the VM, %u division-by-zero, %u float "
      "results\n",
      cases, ran, errors_expected, floats);
}

}  // namespace
}  // namespace uprog::differential
