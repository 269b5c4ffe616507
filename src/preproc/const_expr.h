// The constant expressions of #define, #if and #elseif (Gold manual 2.10): numbers, #define
// values and the operators of manual 1.4, computed with the number rules of manual 1.3-1.6.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "support/value.h"

namespace uprog::preproc {

enum class EvalStatus {
  Ok,
  Empty,              // nothing but blanks
  Syntax,             // not an expression
  UnknownIdentifier,  // an identifier the lookup did not know
  DivisionByZero,
  OutOfRange,  // a float at or beyond 1e37 (manual 1.3), or an over-long hex number
  TooDeep,     // parentheses or unary operators nested beyond kMaxEvalDepth
};

inline constexpr int kMaxEvalDepth = 256;

struct EvalResult {
  EvalStatus status = EvalStatus::Ok;
  TypedValue value = TypedValue::of_int(0);
  size_t error_at = 0;  // offset in the text of the token that failed
  std::string detail;   // a short explanation for a diagnostic note
};

// The value of an identifier, or nullopt when it has none.
using IdentifierLookup = std::function<std::optional<TypedValue>(std::string_view)>;

EvalResult evaluate_constant(std::string_view text, const IdentifierLookup& lookup);

// The text that replaces an identifier whose #define has this value: a number the dialect's
// lexer reads back as the same type and value, in parentheses when negative.
std::string format_constant(TypedValue v);

// #if's test: a non-zero int or float.
inline bool is_true(TypedValue v) { return v.is_float() ? v.value.f != 0.0f : v.value.i != 0; }

}  // namespace uprog::preproc
