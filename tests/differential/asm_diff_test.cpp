// Differential test through uprog assembly: the same random expressions lowered to typed
// opcodes (wrapping MULI) and to dynamic pairs (promoting MULD), assembled, run on the VM and
// compared with the reference.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "asm_text.h"
#include "bytecode/assembly.h"
#include "expr_tree.h"
#include "gold_text.h"
#include "vm_runner.h"

namespace uprog::differential {
namespace {

uint32_t cases_per_run(uint32_t fallback) {
  const char* n = std::getenv("UPROG_DIFF_CASES");
  return n != nullptr ? static_cast<uint32_t>(std::strtoul(n, nullptr, 10)) : fallback;
}

void run_style(AsmStyle style, uint32_t seed) {
  const uint32_t cases = cases_per_run(3000);
  Generator gen(seed);
  uint32_t failures = 0, errors_expected = 0, floats = 0;
  for (uint32_t n = 0; n < cases; ++n) {
    const Vars vars = gen.vars();
    const auto expr = gen.expression(1 + static_cast<int>(gen.below(5)));
    const Outcome want =
        evaluate(*expr, vars, style == AsmStyle::Typed ? IntMul::Wrap : IntMul::Promote);
    const std::string text = asm_program(*expr, vars, style);
    bytecode::Image image;
    std::vector<Diagnostic> diagnostics;
    std::string got;
    bool ok = false;
    if (!bytecode::assemble(text, "differential.s", image, diagnostics)) {
      got = "assembly error: " + format_text(diagnostics);
    } else {
      VmRun run;
      run.run(image);
      if (!run.loaded) {
        got = "the VM refused the image";
      } else if (want.division_by_zero) {
        ok = run.end == vm::SliceEnd::Error && run.error == vm::RunError::DivisionByZero;
        got = "end " + std::to_string(static_cast<int>(run.end)) + ", error " +
              std::to_string(static_cast<int>(run.error));
      } else if (run.end != vm::SliceEnd::Finished) {
        got = "end " + std::to_string(static_cast<int>(run.end)) + ", error " +
              std::to_string(static_cast<int>(run.error));
      } else {
        Num shown;
        if (style == AsmStyle::Typed) {
          const bool is_float = statically_float(*expr);
          shown = is_float
                      ? Num::of_float(run.global(static_cast<uint32_t>(image.find_global("rf"))).f)
                      : Num::of_int(run.global(static_cast<uint32_t>(image.find_global("ri"))).i);
        } else {
          const Value v = run.global(static_cast<uint32_t>(image.find_global("rv")));
          const bool is_float = run.global(static_cast<uint32_t>(image.find_global("rt"))).i != 0;
          shown = is_float ? Num::of_float(v.f) : Num::of_int(v.i);
        }
        ok = same(shown, want.value);
        got = describe(shown);
      }
    }
    errors_expected += want.division_by_zero;
    floats += !want.division_by_zero && want.value.is_float;
    if (!ok && ++failures <= 25) {
      ADD_FAILURE() << "case " << n << " (seed " << seed << "): " << gold_text(*expr, 1)
                    << "\n  reference: "
                    << (want.division_by_zero ? "division by zero" : describe(want.value))
                    << "\n  VM:        " << got << "\n"
                    << text;
    }
  }
  EXPECT_EQ(failures, 0u) << "of " << cases << " cases";
  EXPECT_GT(errors_expected, 0u);
  EXPECT_GT(floats, cases / 10);
  std::printf("[ differential ] %s: %u cases, %u division-by-zero, %u float results\n",
              style == AsmStyle::Typed ? "asm typed" : "asm pairs", cases, errors_expected, floats);
}

TEST(DifferentialAsm, TypedOpcodesMatchTheReference) { run_style(AsmStyle::Typed, 7001u); }
TEST(DifferentialAsm, DynamicPairsMatchTheReference) { run_style(AsmStyle::Pairs, 7002u); }

}  // namespace
}  // namespace uprog::differential
