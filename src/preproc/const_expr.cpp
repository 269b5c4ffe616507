// Recursive-descent evaluation of preprocessor constant expressions. Binary levels loop, so
// only parentheses and unary operators recurse, and they are bounded by kMaxEvalDepth.
#include "preproc/const_expr.h"

#include <charconv>
#include <cmath>
#include <cstdint>

#include "preproc/line_scanner.h"
#include "support/arith.h"

namespace uprog::preproc {
namespace {

constexpr double kFloatLimit = 1e37;  // manual 1.3: -1e37 < N < 1e37

bool is_hex_digit(char c) {
  return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}
int hex_value(char c) {
  if (is_digit(c)) return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return c - 'A' + 10;
}

int32_t to_int(TypedValue v) { return v.is_float() ? arith::trunc_to_int(v.value.f) : v.value.i; }
bool nonzero(TypedValue v) { return is_true(v); }
TypedValue of_bool(bool b) { return TypedValue::of_int(b ? 1 : 0); }

// Binary operators, with the precedence of manual 1.4 (higher binds tighter).
enum class Op { Or, And, BitOr, BitAnd, Eq, Ne, Lt, Le, Gt, Ge, Shl, Shr, Add, Sub, Mul, Div, Rem };

struct OpInfo {
  Op op;
  int precedence;
  size_t length;
};

class Evaluator {
 public:
  Evaluator(std::string_view text, const IdentifierLookup& lookup) : text_(text), lookup_(lookup) {}

  EvalResult run() {
    skip_blanks();
    if (pos_ >= text_.size()) return fail(EvalStatus::Empty, "the expression is empty");
    TypedValue v = parse_binary(kLowestPrecedence);
    if (result_.status != EvalStatus::Ok) return result_;
    skip_blanks();
    if (pos_ < text_.size())
      return fail(EvalStatus::Syntax, "unexpected text after the expression");
    result_.value = v;
    return result_;
  }

 private:
  static constexpr int kLowestPrecedence = 7;

  EvalResult fail(EvalStatus s, std::string detail) { return fail_at(s, pos_, std::move(detail)); }
  EvalResult fail_at(EvalStatus s, size_t at, std::string detail) {
    if (result_.status == EvalStatus::Ok) {
      result_.status = s;
      result_.error_at = at;
      result_.detail = std::move(detail);
    }
    return result_;
  }
  bool failed() const { return result_.status != EvalStatus::Ok; }

  void skip_blanks() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r'))
      ++pos_;
  }
  char peek(size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }

  std::optional<OpInfo> peek_binary() const {
    const char c = peek(), d = peek(1);
    switch (c) {
      case '|':
        return d == '|' ? OpInfo{Op::Or, 7, 2} : OpInfo{Op::BitOr, 9, 1};
      case '&':
        return d == '&' ? OpInfo{Op::And, 8, 2} : OpInfo{Op::BitAnd, 11, 1};
      case '=':
        if (d == '=') return OpInfo{Op::Eq, 12, 2};
        return std::nullopt;
      case '!':
        if (d == '=') return OpInfo{Op::Ne, 12, 2};
        return std::nullopt;
      case '<':
        if (d == '<') return OpInfo{Op::Shl, 14, 2};
        return d == '=' ? OpInfo{Op::Le, 13, 2} : OpInfo{Op::Lt, 13, 1};
      case '>':
        if (d == '>') return OpInfo{Op::Shr, 14, 2};
        return d == '=' ? OpInfo{Op::Ge, 13, 2} : OpInfo{Op::Gt, 13, 1};
      case '+':
        return OpInfo{Op::Add, 15, 1};
      case '-':
        return OpInfo{Op::Sub, 15, 1};
      case '*':
        return OpInfo{Op::Mul, 16, 1};
      case '/':
        return OpInfo{Op::Div, 16, 1};
      case '%':
        return OpInfo{Op::Rem, 16, 1};
      default:
        return std::nullopt;
    }
  }

  // Left-associative precedence climbing; every level is a loop, not a recursion per operator.
  TypedValue parse_binary(int min_precedence) {
    TypedValue left = parse_unary(0);
    while (!failed()) {
      skip_blanks();
      const auto info = peek_binary();
      if (!info || info->precedence < min_precedence) break;
      const size_t op_at = pos_;
      pos_ += info->length;
      TypedValue right = parse_binary_above(info->precedence);
      if (failed()) break;
      left = apply(info->op, left, right, op_at);
    }
    return left;
  }
  // The right operand binds everything tighter than `precedence`. Levels are few (7..16),
  // so this recursion is bounded by the table, not by the input.
  TypedValue parse_binary_above(int precedence) {
    if (precedence >= 16) return parse_unary(0);
    return parse_binary(precedence + 1);
  }

  TypedValue parse_unary(int depth) {
    skip_blanks();
    if (depth > kMaxEvalDepth) {
      fail(EvalStatus::TooDeep, "the expression is nested too deeply");
      return TypedValue::of_int(0);
    }
    const char c = peek();
    if (c == '-' || c == '!' || c == '~') {
      ++pos_;
      const TypedValue v = parse_unary(depth + 1);
      if (failed()) return v;
      if (c == '!') return of_bool(to_int(v) == 0);  // manual 1.6: !0.0004 yields 1
      if (c == '~') return TypedValue::of_int(~to_int(v));
      return v.is_float() ? TypedValue::of_float(-v.value.f)
                          : TypedValue::of_int(arith::saturating_neg(v.value.i));
    }
    if (c == '(') {
      const size_t open_at = pos_;
      ++pos_;
      if (depth + nesting_ > kMaxEvalDepth) {
        fail(EvalStatus::TooDeep, "the expression is nested too deeply");
        return TypedValue::of_int(0);
      }
      ++nesting_;
      const TypedValue v = parse_binary(kLowestPrecedence);
      --nesting_;
      if (failed()) return v;
      skip_blanks();
      if (peek() != ')') {
        fail_at(EvalStatus::Syntax, open_at, "'(' without ')'");
        return v;
      }
      ++pos_;
      return v;
    }
    if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return parse_number();
    if (is_ident_start(c)) return parse_identifier();
    if (pos_ >= text_.size())
      fail(EvalStatus::Syntax, "an operand is missing at the end");
    else
      fail(EvalStatus::Syntax, "an operand is expected here");
    return TypedValue::of_int(0);
  }

  TypedValue parse_identifier() {
    const size_t begin = pos_;
    while (pos_ < text_.size() && is_ident_char(text_[pos_])) ++pos_;
    const std::string_view name = text_.substr(begin, pos_ - begin);
    if (auto v = lookup_(name)) return *v;
    fail_at(EvalStatus::UnknownIdentifier, begin,
            "'" + std::string(name) + "' has no constant value");
    return TypedValue::of_int(0);
  }

  // A number token runs over letters, digits, '.', and a sign after a decimal exponent.
  TypedValue parse_number() {
    const size_t begin = pos_;
    const bool hex = peek() == '0' && (peek(1) == 'x' || peek(1) == 'X');
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      const bool exponent_sign = !hex && (c == '+' || c == '-') && pos_ > begin &&
                                 (text_[pos_ - 1] == 'e' || text_[pos_ - 1] == 'E');
      if (!is_ident_char(c) && c != '.' && !exponent_sign) break;
      ++pos_;
    }
    const std::string_view token = text_.substr(begin, pos_ - begin);
    if (hex) return hex_number(token, begin);
    if (token.find_first_of(".eE") != std::string_view::npos) return float_number(token, begin);
    return decimal_number(token, begin);
  }

  TypedValue hex_number(std::string_view token, size_t at) {
    const std::string_view digits = token.substr(2);
    if (digits.empty()) return bad_number(token, at);
    uint32_t bits = 0;
    for (const char c : digits) {
      if (!is_hex_digit(c)) return bad_number(token, at);
    }
    if (digits.size() > 8) {
      fail_at(EvalStatus::OutOfRange, at, "'" + std::string(token) + "' has more than 32 bits");
      return TypedValue::of_int(0);
    }
    for (const char c : digits) bits = (bits << 4) | static_cast<uint32_t>(hex_value(c));
    return TypedValue{Value::of_bits(bits), ValueType::Int};
  }

  // digits [. digits] [e [+-] digits], with at least one mantissa digit.
  TypedValue float_number(std::string_view token, size_t at) {
    size_t i = 0, mantissa_digits = 0;
    while (i < token.size() && is_digit(token[i])) ++i, ++mantissa_digits;
    if (i < token.size() && token[i] == '.') {
      ++i;
      while (i < token.size() && is_digit(token[i])) ++i, ++mantissa_digits;
    }
    if (mantissa_digits == 0) return bad_number(token, at);
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
      ++i;
      if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
      size_t exponent_digits = 0;
      while (i < token.size() && is_digit(token[i])) ++i, ++exponent_digits;
      if (exponent_digits == 0) return bad_number(token, at);
    }
    if (i != token.size()) return bad_number(token, at);
    return float_value(token, at);
  }

  TypedValue float_value(std::string_view token, size_t at) {
    double d = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), d);
    if (ec == std::errc::result_out_of_range ||
        (ec == std::errc() && std::fabs(d) >= kFloatLimit)) {
      fail_at(EvalStatus::OutOfRange, at, "'" + std::string(token) + "' is beyond the float range");
      return TypedValue::of_int(0);
    }
    if (ec != std::errc() || end != token.data() + token.size()) return bad_number(token, at);
    return TypedValue::of_float(static_cast<float>(d));
  }

  // Manual 1.3: an integer beyond the int range becomes a float.
  TypedValue decimal_number(std::string_view token, size_t at) {
    uint64_t v = 0;
    for (const char c : token) {
      if (!is_digit(c)) return bad_number(token, at);
      if (v <= INT32_MAX) v = v * 10 + static_cast<uint64_t>(c - '0');
    }
    if (v <= INT32_MAX) return TypedValue::of_int(static_cast<int32_t>(v));
    return float_value(token, at);
  }

  TypedValue bad_number(std::string_view token, size_t at) {
    fail_at(EvalStatus::Syntax, at, "'" + std::string(token) + "' is not a number");
    return TypedValue::of_int(0);
  }

  TypedValue checked_float(float f, size_t at) {
    if (!std::isfinite(f) || std::fabs(f) >= static_cast<float>(kFloatLimit)) {
      fail_at(EvalStatus::OutOfRange, at, "the result is beyond the float range");
      return TypedValue::of_int(0);
    }
    return TypedValue::of_float(f);
  }

  TypedValue apply(Op op, TypedValue a, TypedValue b, size_t at) {
    const bool ints = !a.is_float() && !b.is_float();
    const float fa = a.as_float(), fb = b.as_float();
    switch (op) {
      // Manual 1.6's examples test && and || for non-zero (0.21&&2 yields 1), not truncated.
      case Op::Or:
        return of_bool(nonzero(a) || nonzero(b));
      case Op::And:
        return of_bool(nonzero(a) && nonzero(b));
      case Op::BitOr:
        return TypedValue::of_int(to_int(a) | to_int(b));
      case Op::BitAnd:
        return TypedValue::of_int(to_int(a) & to_int(b));
      case Op::Eq:
        return of_bool(ints ? a.value.i == b.value.i : fa == fb);
      case Op::Ne:
        return of_bool(ints ? a.value.i != b.value.i : fa != fb);
      case Op::Lt:
        return of_bool(ints ? a.value.i < b.value.i : fa < fb);
      case Op::Le:
        return of_bool(ints ? a.value.i <= b.value.i : fa <= fb);
      case Op::Gt:
        return of_bool(ints ? a.value.i > b.value.i : fa > fb);
      case Op::Ge:
        return of_bool(ints ? a.value.i >= b.value.i : fa >= fb);
      case Op::Shl:
        return TypedValue::of_int(arith::shift_left(to_int(a), to_int(b)));
      case Op::Shr:
        return TypedValue::of_int(arith::shift_right(to_int(a), to_int(b)));
      case Op::Add:
        return ints ? TypedValue::of_int(arith::wrap_add(a.value.i, b.value.i))
                    : checked_float(fa + fb, at);
      case Op::Sub:
        return ints ? TypedValue::of_int(arith::wrap_sub(a.value.i, b.value.i))
                    : checked_float(fa - fb, at);
      case Op::Mul: {
        if (!ints) return checked_float(fa * fb, at);
        const auto p = arith::promoting_mul(a.value.i, b.value.i);
        return p.is_float ? checked_float(p.f, at) : TypedValue::of_int(p.i);
      }
      case Op::Div:
        if (ints ? b.value.i == 0 : fb == 0.0f) {
          fail_at(EvalStatus::DivisionByZero, at, "division by zero");
          return TypedValue::of_int(0);
        }
        return ints ? TypedValue::of_int(arith::int_div(a.value.i, b.value.i))
                    : checked_float(fa / fb, at);
      case Op::Rem: {
        const int32_t ia = to_int(a), ib = to_int(b);  // manual 1.6: % yields an integer
        if (ib == 0) {
          fail_at(EvalStatus::DivisionByZero, at, "remainder of a division by zero");
          return TypedValue::of_int(0);
        }
        return TypedValue::of_int(arith::int_rem(ia, ib));
      }
    }
    return TypedValue::of_int(0);
  }

  std::string_view text_;
  const IdentifierLookup& lookup_;
  size_t pos_ = 0;
  int nesting_ = 0;
  EvalResult result_;
};

}  // namespace

EvalResult evaluate_constant(std::string_view text, const IdentifierLookup& lookup) {
  return Evaluator(text, lookup).run();
}

std::string format_constant(TypedValue v) {
  if (!v.is_float()) {
    // The lexer cannot read 2147483648; manual 1.3 writes the lowest int in hex.
    if (v.value.i == INT32_MIN) return "0x80000000";
    const std::string digits = std::to_string(v.value.i);
    return v.value.i < 0 ? "(" + digits + ")" : digits;
  }
  // Manual 1.3: a number whose part left or right of the point exceeds 2147483647 is a syntax
  // error, so large and tiny values are written with an exponent.
  const float magnitude = std::fabs(v.value.f);
  const bool exponent = magnitude >= 1e9f || (magnitude != 0.0f && magnitude < 1e-4f);
  char buf[64];
  const auto [end, ec] =
      exponent ? std::to_chars(buf, buf + sizeof buf, v.value.f, std::chars_format::scientific)
               : std::to_chars(buf, buf + sizeof buf, v.value.f);
  std::string s = ec == std::errc() ? std::string(buf, end) : std::string("0");
  // The shortest form may look like an int ("25000", "1e+10"): give the mantissa a point, so
  // the lexer reads a float, and drop the exponent's '+'.
  const size_t e = s.find('e');
  const std::string_view mantissa = std::string_view(s).substr(0, e);
  if (mantissa.find('.') == std::string_view::npos)
    s.insert(e == std::string::npos ? s.size() : e, ".0");
  const size_t plus = s.find("e+");
  if (plus != std::string::npos) s.erase(plus + 1, 1);
  return s[0] == '-' ? "(" + s + ")" : s;
}

}  // namespace uprog::preproc
