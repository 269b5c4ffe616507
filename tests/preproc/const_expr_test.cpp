// The constant evaluator on its own: types of results (manual 2.10: logical, bitwise and
// comparison results are ints; calculation results are float when an operand is), number
// forms of manual 1.3, and the errors it reports.
#include "preproc/const_expr.h"

#include <gtest/gtest.h>

#include <string>

namespace uprog::preproc {
namespace {

std::optional<TypedValue> no_names(std::string_view) { return std::nullopt; }

EvalResult eval(const std::string& s) { return evaluate_constant(s, no_names); }

TEST(preproc_const_expr, ResultTypesFollowManual210) {
  EXPECT_FALSE(eval("1+2").value.is_float());
  EXPECT_TRUE(eval("1+2.0").value.is_float());
  EXPECT_FALSE(eval("1.5 < 2.5").value.is_float());
  EXPECT_FALSE(eval("7.9 & 3.4").value.is_float());
  EXPECT_FALSE(eval("5.5 % 2").value.is_float());
  EXPECT_FALSE(eval("0.5 && 0.5").value.is_float());
  EXPECT_TRUE(eval("-4.5").value.is_float());
  EXPECT_TRUE(eval("100000*100000").value.is_float());  // manual 1.5
  EXPECT_FALSE(eval("46340*46340").value.is_float());   // still fits
}

TEST(preproc_const_expr, NumberForms) {
  EXPECT_EQ(eval("0x10").value.value.i, 16);  // manual 1.3.1
  EXPECT_EQ(eval("0X7fffffff").value.value.i, INT32_MAX);
  EXPECT_EQ(eval("0x80000000").value.value.i, INT32_MIN);  // manual 1.3 note
  EXPECT_FLOAT_EQ(eval("2.5e4").value.value.f, 25000.0f);  // manual 1.3.2
  EXPECT_FLOAT_EQ(eval("2.55e-3").value.value.f, 0.00255f);
  EXPECT_FLOAT_EQ(eval(".5").value.value.f, 0.5f);
  EXPECT_FLOAT_EQ(eval("3.").value.value.f, 3.0f);
  EXPECT_TRUE(eval("2147483648").value.is_float());  // manual 1.3: beyond int becomes float
  EXPECT_EQ(eval("2147483647").value.value.i, INT32_MAX);
  EXPECT_EQ(eval("-2147483647-1").value.value.i, INT32_MIN);
}

TEST(preproc_const_expr, Errors) {
  EXPECT_EQ(eval("").status, EvalStatus::Empty);
  EXPECT_EQ(eval("  \t ").status, EvalStatus::Empty);
  EXPECT_EQ(eval("1 2").status, EvalStatus::Syntax);
  EXPECT_EQ(eval("(1").status, EvalStatus::Syntax);
  EXPECT_EQ(eval("1)").status, EvalStatus::Syntax);
  EXPECT_EQ(eval("0x").status, EvalStatus::Syntax);
  EXPECT_EQ(eval("1e").status, EvalStatus::Syntax);
  EXPECT_EQ(eval("1.2.3").status, EvalStatus::Syntax);
  EXPECT_EQ(eval("1 = 1").status, EvalStatus::Syntax);  // assignment is no constant operator
  EXPECT_EQ(eval("0x123456789").status, EvalStatus::OutOfRange);
  EXPECT_EQ(eval("1e37").status, EvalStatus::OutOfRange);  // manual 1.3: -1e37 < N < 1e37
  EXPECT_EQ(eval("1e36*100").status, EvalStatus::OutOfRange);
  EXPECT_EQ(eval("1/0").status, EvalStatus::DivisionByZero);
  EXPECT_EQ(eval("1%0.5").status, EvalStatus::DivisionByZero);  // 0.5 truncates to 0
  EXPECT_EQ(eval("X").status, EvalStatus::UnknownIdentifier);
  EXPECT_EQ(eval(std::string(10000, '(') + "1" + std::string(10000, ')')).status,
            EvalStatus::TooDeep);
  EXPECT_EQ(eval(std::string(10000, '-') + "1").status, EvalStatus::TooDeep);
  EXPECT_EQ(eval(std::string(100, '(') + "1" + std::string(100, ')')).status, EvalStatus::Ok);
}

TEST(preproc_const_expr, ErrorOffsetPointsAtTheToken) {
  EXPECT_EQ(eval(" 1 + X").error_at, 5u);
  EXPECT_EQ(eval("4 / 0").error_at, 2u);
}

TEST(preproc_const_expr, IdentifiersUseTheLookup) {
  const IdentifierLookup lookup = [](std::string_view n) -> std::optional<TypedValue> {
    if (n == "TEN") return TypedValue::of_int(10);
    if (n == "HALF") return TypedValue::of_float(0.5f);
    return std::nullopt;
  };
  EXPECT_EQ(evaluate_constant("TEN*TEN", lookup).value.value.i, 100);
  EXPECT_FLOAT_EQ(evaluate_constant("TEN*HALF", lookup).value.value.f, 5.0f);
  EXPECT_EQ(evaluate_constant("TEN_", lookup).status, EvalStatus::UnknownIdentifier);
}

TEST(preproc_const_expr, ArithmeticEdges) {
  EXPECT_EQ(eval("-0x80000000").value.value.i, INT32_MAX);  // manual 1.5
  EXPECT_EQ(eval("0x80000000/-1").value.value.i, INT32_MAX);
  EXPECT_EQ(eval("-7/2").value.value.i, -3);  // truncates toward zero
  EXPECT_EQ(eval("1<<40").value.value.i, 0);
  EXPECT_EQ(eval("-8>>1").value.value.i, -4);
  EXPECT_EQ(eval("~3.2").value.value.i, -4);
}

TEST(preproc_const_expr, FormatReadsBack) {
  EXPECT_EQ(format_constant(TypedValue::of_int(42)), "42");
  EXPECT_EQ(format_constant(TypedValue::of_int(-42)), "(-42)");
  EXPECT_EQ(format_constant(TypedValue::of_int(INT32_MIN)), "0x80000000");
  EXPECT_EQ(format_constant(TypedValue::of_float(25000.0f)), "25000.0");
  EXPECT_EQ(format_constant(TypedValue::of_float(0.5f)), "0.5");
  EXPECT_EQ(format_constant(TypedValue::of_float(-1e10f)), "(-1.0e10)");
  EXPECT_EQ(format_constant(TypedValue::of_float(1.5e-20f)), "1.5e-20");
  EXPECT_EQ(format_constant(TypedValue::of_float(2147483648.0f)),
            "2.1474836e09");  // not 2147483648.0
  EXPECT_EQ(format_constant(TypedValue::of_float(1e-5f)), "1.0e-05");
  // Whatever is printed evaluates back to the same value and type.
  for (float f : {0.1f, 3.14159f, 1e30f, -2.5e-7f, 123456789.0f, 0.0f}) {
    const EvalResult r = eval(format_constant(TypedValue::of_float(f)));
    ASSERT_EQ(r.status, EvalStatus::Ok) << f;
    EXPECT_TRUE(r.value.is_float());
    EXPECT_EQ(r.value.value.f, f);
  }
  for (int32_t i : {0, 1, -1, INT32_MAX, INT32_MIN + 1, INT32_MIN}) {
    const EvalResult r = eval(format_constant(TypedValue::of_int(i)));
    ASSERT_EQ(r.status, EvalStatus::Ok) << i;
    EXPECT_FALSE(r.value.is_float());
    EXPECT_EQ(r.value.value.i, i);
  }
}

}  // namespace
}  // namespace uprog::preproc
