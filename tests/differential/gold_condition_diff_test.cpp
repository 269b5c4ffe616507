// Differential test of Gold's conditions: random expressions as the condition of `if`, `while`
// (jumps when false) and `until` (jumps when true) in a program, run on the VM and compared with
// the reference's truth of the same expression. A condition's && and || jump on each side when
// the right side shows nothing (codegen.cpp); an expression's value evaluates both sides
// (docs/dialects/gold.md, decision 4): the two must agree, and a division by zero on either
// side is still an error.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "dialects/gold/compile.h"
#include "expr_tree.h"
#include "gold_text.h"
#include "vm_runner.h"

namespace uprog::differential {
namespace {

const char kDeclarations[] =
    "int i0, i1, i2, i3\nfloat f0, f1, f2, f3\nint r, w, u\nfunction main()\n"
    "global int i0, i1, i2, i3\nglobal float f0, f1, f2, f3\nglobal int r, w, u\n";

// A Gold line holds 128 characters (error 51); `until (`, the longest, and `)` take 8.
constexpr size_t kLongestCondition = 120;

// The variables' assignments, one a line.
std::string assignments(const Vars& vars) {
  std::string lines = gold_assignments(vars);
  for (size_t at = lines.find("; "); at != std::string::npos; at = lines.find("; ", at))
    lines.replace(at, 2, "\n");
  return lines;
}

struct Ran {
  bool compiled = false, refused_division = false;
  std::string diagnostics;
  VmRun run;
};

void compile_and_run(const std::string& body, Ran& out) {
  const gold::CompileResult program =
      gold::compile(SourceFile{"condition.ehl", kDeclarations + body + "return\n"});
  out.compiled = program.ok();
  // A division by a constant zero may be refused at compile time ("Division by zero", 86; the
  // `if` and the `while` each say so).
  out.refused_division = !program.ok();
  for (const Diagnostic& d : program.diagnostics) out.refused_division &= d.code == 86;
  out.diagnostics = format_text(program.diagnostics);
  if (out.compiled) out.run.run(program.image);
}

int32_t global_named(const VmRun& run, const bytecode::Image& image, const char* name) {
  for (uint32_t g = 0; g < image.globals.size(); ++g)
    if (image.globals[g].name == name) return run.global(g).i;
  return -1;
}

TEST(DifferentialGoldCondition, RandomConditionsMatchTheReferenceTruth) {
  const char* seed_text = std::getenv("UPROG_DIFF_SEED");
  Generator gen(seed_text != nullptr ? static_cast<uint32_t>(std::strtoul(seed_text, nullptr, 10))
                                     : 20261207u);
  const gold::CompileResult program =
      gold::compile(SourceFile{"names.ehl", std::string(kDeclarations) + "return\n"});
  ASSERT_TRUE(program.ok()) << format_text(program.diagnostics);
  const bytecode::Image& names = program.image;  // every case's globals, in the same order
  uint32_t tried = 0, failures = 0, true_cases = 0, false_cases = 0, errors = 0;
  const uint32_t cases = 3000;
  for (uint32_t n = 0; n < cases; ++n) {
    const Vars vars = gen.vars();
    const auto expr = gen.expression(1 + static_cast<int>(gen.below(5)));
    const Outcome want = evaluate(*expr, vars, IntMul::Promote);
    const bool truth = want.value.is_float ? want.value.f != 0.0f : want.value.i != 0;
    const std::string condition = gold_text(*expr, n * 2654435761u + 1);
    if (condition.size() > kLongestCondition) continue;
    ++tried;
    const std::string set = assignments(vars);
    Ran branches, waits;
    compile_and_run(set + "r = 0\nif (" + condition + ")\n  r = 1\nend\nw = 0\nwhile (" +
                        condition + ")\n  w = 1\n  break\nend\n",
                    branches);
    compile_and_run(set + "until (" + condition + ")\nu = 1\n", waits);
    std::string got;
    bool ok = false;
    if (!branches.compiled || !waits.compiled) {
      ok = want.division_by_zero && branches.refused_division && waits.refused_division;
      got = "not compiled: " + branches.diagnostics + waits.diagnostics;
    } else if (want.division_by_zero) {
      ok = branches.run.error == vm::RunError::DivisionByZero &&
           waits.run.error == vm::RunError::DivisionByZero;
      got = "errors " + std::to_string(static_cast<int>(branches.run.error)) + ", " +
            std::to_string(static_cast<int>(waits.run.error));
    } else {
      const int32_t r = global_named(branches.run, names, "r");
      const int32_t w = global_named(branches.run, names, "w");
      const bool passed = waits.run.end == vm::SliceEnd::Finished;
      ok = branches.run.end == vm::SliceEnd::Finished && r == truth && w == truth &&
           passed == truth && waits.run.error == vm::RunError::None &&
           global_named(waits.run, names, "u") == (truth ? 1 : 0);
      got = "if " + std::to_string(r) + ", while " + std::to_string(w) + ", until " +
            (passed ? "passed" : "waits");
    }
    errors += want.division_by_zero;
    (truth ? true_cases : false_cases) += !want.division_by_zero;
    if (!ok && ++failures <= 25)
      ADD_FAILURE() << "case " << n << ": " << condition << "\n  reference: "
                    << (want.division_by_zero ? "division by zero"
                        : truth               ? "true"
                                              : "false")
                    << "\n  VM:        " << got;
  }
  EXPECT_EQ(failures, 0u) << "of " << tried << " cases";
  // Most cases fit a line, and they reach both outcomes and the error.
  EXPECT_GT(tried, cases * 3 / 4);
  EXPECT_GT(true_cases, tried / 10);
  EXPECT_GT(false_cases, tried / 10);
  EXPECT_GT(errors, 0u);
}

}  // namespace
}  // namespace uprog::differential
