// Generates random expressions and evaluates them by the reference rules (reference.h).
#include "expr_tree.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace uprog::differential {

bool is_leaf(Op op) { return op <= Op::FloatVar; }
bool is_unary(Op op) { return op >= Op::Neg && op <= Op::Sqrt; }

namespace {

Outcome value(Num n) { return {false, n}; }
Outcome error() { return {true, {}}; }
Num I(int32_t v) { return Num::of_int(v); }
Num F(float v) { return Num::of_float(v); }

int32_t wrap(int64_t v) {
  return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(v)));
}

// Operands of bitwise and logical-not operators are truncated to integers (1.6).
int32_t as_int(Num x) { return x.is_float ? ref::truncate_to_int(x.f) : x.i; }

Outcome unary(Op op, Num x) {
  using namespace ref;
  switch (op) {
    case Op::Neg:
      if (x.is_float) return value(F(-x.f));
      return value(I(x.i == INT32_MIN ? INT32_MAX : -x.i));  // 1.5: -0x80000000 is 0x7FFFFFFF
    case Op::Not:
      return value(I(as_int(x) == 0 ? 1 : 0));  // 1.6: !0.0004 is 1
    case Op::BitNot:
      return value(I(~as_int(x)));
    case Op::Abs:
      if (x.is_float) return value(F(std::fabs(x.f)));
      return value(I(x.i == INT32_MIN ? INT32_MAX : (x.i < 0 ? -x.i : x.i)));
    case Op::Sign: {
      const double d = x.is_float ? static_cast<double>(x.f) : static_cast<double>(x.i);
      return value(I(d > 0 ? 1 : d < 0 ? -1 : 0));
    }
    case Op::Fix:
      return value(I(x.is_float ? truncate_to_int(x.f) : x.i));
    case Op::Rnd:
      return value(I(x.is_float ? round_to_int(x.f) : x.i));
    case Op::Real:
      return value(F(to_float(x)));
    case Op::Sqrt: {
      const float v = to_float(x);
      return value(F(v < 0 ? 0.0f : to_f32(std::sqrt(static_cast<double>(v)))));
    }
    default:
      std::abort();
  }
}

Outcome binary(Op op, Num x, Num y, IntMul mul) {
  using namespace ref;
  const bool ints = !x.is_float && !y.is_float;
  const double fx = to_float(x), fy = to_float(y);  // exact in double
  switch (op) {
    case Op::Add:
      return value(ints ? I(wrap(int64_t{x.i} + y.i)) : F(to_f32(fx + fy)));
    case Op::Sub:
      return value(ints ? I(wrap(int64_t{x.i} - y.i)) : F(to_f32(fx - fy)));
    case Op::Mul: {
      if (!ints) return value(F(to_f32(fx * fy)));
      const int64_t p = int64_t{x.i} * y.i;
      if (mul == IntMul::Wrap) return value(I(wrap(p)));
      if (p >= INT32_MIN && p <= INT32_MAX) return value(I(static_cast<int32_t>(p)));
      return value(F(static_cast<float>(p)));  // 1.5: converted, not truncated
    }
    case Op::Div:
      if (ints) {
        if (y.i == 0) return error();
        if (x.i == INT32_MIN && y.i == -1) return value(I(INT32_MAX));
        return value(I(x.i / y.i));  // toward zero (1.5: 5/2 is 2)
      }
      if (fy == 0.0) return error();
      return value(F(to_f32(fx / fy)));
    case Op::Rem: {
      const int32_t a = as_int(x), b = as_int(y);
      if (b == 0) return error();
      if (b == -1) return value(I(0));
      return value(I(a % b));
    }
    case Op::And:
      return value(I(as_int(x) & as_int(y)));
    case Op::Or:
      return value(I(as_int(x) | as_int(y)));
    case Op::Shl: {
      const int32_t a = as_int(x), n = as_int(y);
      if (n < 0 || n > 31) return value(I(0));
      return value(I(static_cast<int32_t>(static_cast<uint32_t>(a) << n)));
    }
    case Op::Shr: {
      const int32_t a = as_int(x), n = as_int(y);
      if (n < 0 || n > 31) return value(I(a < 0 ? -1 : 0));
      // Arithmetic: floor(a / 2^n), written without >> so that it is independent.
      return value(
          I(static_cast<int32_t>(std::floor(static_cast<double>(a) / std::ldexp(1.0, n)))));
    }
    case Op::Lt:
      return value(I(ints ? x.i < y.i : fx < fy));
    case Op::Le:
      return value(I(ints ? x.i <= y.i : fx <= fy));
    case Op::Gt:
      return value(I(ints ? x.i > y.i : fx > fy));
    case Op::Ge:
      return value(I(ints ? x.i >= y.i : fx >= fy));
    case Op::Eq:
      return value(I(ints ? x.i == y.i : fx == fy));
    case Op::Ne:
      return value(I(ints ? x.i != y.i : fx != fy));
    case Op::LogAnd:
      return value(I(truth(x) && truth(y)));
    case Op::LogOr:
      return value(I(truth(x) || truth(y)));
    default:
      std::abort();
  }
}

}  // namespace

Outcome evaluate(const Expr& e, const Vars& vars, IntMul mul) {
  switch (e.op) {
    case Op::IntLit:
    case Op::FloatLit:
      return value(e.literal);
    case Op::IntVar:
      return value(I(vars.i[e.var]));
    case Op::FloatVar:
      return value(F(vars.f[e.var]));
    default:
      break;
  }
  const Outcome x = evaluate(*e.a, vars, mul);
  if (x.division_by_zero) return x;
  if (is_unary(e.op)) return unary(e.op, x.value);
  const Outcome y = evaluate(*e.b, vars, mul);  // both sides always run (no short circuit)
  if (y.division_by_zero) return y;
  return binary(e.op, x.value, y.value, mul);
}

bool statically_float(const Expr& e) {
  switch (e.op) {
    case Op::IntLit:
    case Op::FloatLit:
      return e.literal.is_float;
    case Op::IntVar:
      return false;
    case Op::FloatVar:
      return true;
    case Op::Neg:
    case Op::Abs:
      return statically_float(*e.a);
    case Op::Real:
    case Op::Sqrt:
      return true;
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
      return statically_float(*e.a) || statically_float(*e.b);
    default:
      return false;
  }
}

int32_t Generator::interesting_int() {
  switch (below(8)) {
    case 0:
      return static_cast<int32_t>(below(10));
    case 1:
      return static_cast<int32_t>(below(1000)) - 500;
    case 2:
      return static_cast<int32_t>(below(100000));
    case 3:
      return static_cast<int32_t>(rng_());  // anything
    case 4:
      return INT32_MAX - static_cast<int32_t>(below(4));
    case 5:
      return INT32_MIN + static_cast<int32_t>(below(4));
    case 6:
      return static_cast<int32_t>(below(70)) - 35;  // shift counts
    default:
      return 46340 + static_cast<int32_t>(below(10)) - 5;  // products near 2^31
  }
}

std::unique_ptr<Expr> Generator::int_literal() {
  auto e = std::make_unique<Expr>();
  e->op = Op::IntLit;
  int32_t v = interesting_int();
  char buf[32];
  if (below(4) == 0) {  // hex: any bit pattern, 0x80000000 included (1.3)
    std::snprintf(buf, sizeof buf, "0x%X", static_cast<uint32_t>(v));
  } else {
    if (v < 0) v = v == INT32_MIN ? INT32_MAX : -v;  // a minus sign would be an operator
    std::snprintf(buf, sizeof buf, "%d", v);
  }
  e->literal = Num::of_int(v);
  e->text = buf;
  return e;
}

std::unique_ptr<Expr> Generator::float_literal() {
  auto e = std::make_unique<Expr>();
  e->op = Op::FloatLit;
  char buf[48];
  switch (below(6)) {
    case 5: {  // an integer beyond the int range is read as a float (1.3)
      const uint64_t v = 2147483648u + below(2000000000u);
      std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(v));
      e->text = buf;
      e->literal = Num::of_float(static_cast<float>(v));
      return e;
    }
    case 0:
      std::snprintf(buf, sizeof buf, "%u.%u", below(100000), below(1000));
      break;
    case 1:
      std::snprintf(buf, sizeof buf, "%u.%02u", below(100), below(100));
      break;
    case 2:
      std::snprintf(buf, sizeof buf, "%u.%ue%d", below(10), below(1000),
                    static_cast<int>(below(13)) - 6);
      break;
    case 3:
      std::snprintf(buf, sizeof buf, "%u.5", below(20));
      break;  // halves: rounding
    default:
      std::snprintf(buf, sizeof buf, "%u.0", below(2000000000u));
      break;
  }
  e->text = buf;
  e->literal = Num::of_float(std::strtof(buf, nullptr));
  return e;
}

std::unique_ptr<Expr> Generator::expression(int depth) {
  if (depth <= 0 || below(5) == 0) {
    auto e = std::make_unique<Expr>();
    switch (below(4)) {
      case 0:
        return int_literal();
      case 1:
        return float_literal();
      case 2:
        e->op = Op::IntVar;
        break;
      default:
        e->op = Op::FloatVar;
        break;
    }
    e->var = static_cast<int>(below(kVars));
    return e;
  }
  auto e = std::make_unique<Expr>();
  if (below(5) == 0) {
    e->op = static_cast<Op>(static_cast<int>(Op::Neg) + static_cast<int>(below(9)));
    e->a = expression(depth - 1);
  } else {
    // Arithmetic twice as often as the rest.
    const uint32_t k = below(26);
    e->op = k < 8 ? static_cast<Op>(static_cast<int>(Op::Add) + static_cast<int>(k % 4))
                  : static_cast<Op>(static_cast<int>(Op::Add) + static_cast<int>((k - 8) % 17));
    e->a = expression(depth - 1);
    e->b = expression(depth - 1);
  }
  return e;
}

Vars Generator::vars() {
  Vars v;
  for (int k = 0; k < kVars; ++k) {
    auto i = int_literal();
    v.i[k] = i->literal.i;
    v.i_text[k] = i->text;
    auto f = float_literal();
    v.f[k] = f->literal.f;
    v.f_text[k] = f->text;
  }
  return v;
}

}  // namespace uprog::differential
