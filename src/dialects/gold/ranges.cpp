// Range analysis of int expressions (constants, loop variables, + - * % &) for the promoting
// multiply: every rule widens to the full range whenever a bound could leave int32.
#include "dialects/gold/ranges.h"

#include <algorithm>

namespace uprog::gold {

namespace {

constexpr IntRange kFull{};
// How deep range_of looks: keeps it linear on long chains (a+a+...+a) and its stack small.
constexpr int kMaxDepth = 32;

bool fits(int64_t lo, int64_t hi) { return lo >= INT32_MIN && hi <= INT32_MAX; }

IntRange checked(int64_t lo, int64_t hi) { return fits(lo, hi) ? IntRange{lo, hi} : kFull; }

bool constant(const Expr& e, int64_t& out) {
  if (e.kind == ExprKind::IntLit) {
    out = e.int_value;
    return true;
  }
  if (e.kind == ExprKind::Unary && e.op == Tok::Minus && e.lhs->kind == ExprKind::IntLit &&
      e.lhs->int_value != INT32_MIN) {
    out = -static_cast<int64_t>(e.lhs->int_value);
    return true;
  }
  return false;
}

IntRange product(const IntRange& a, const IntRange& b) {
  // |bounds| <= 2^31, so every corner product fits in int64.
  const int64_t c[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(c, c + 4), *std::max_element(c, c + 4)};
}

}  // namespace

IntRange range_of(const Expr& e, const std::vector<LoopRange>& loops, int depth) {
  if (e.type != Kind::Int || depth > kMaxDepth) return kFull;
  switch (e.kind) {
    case ExprKind::IntLit:
      return {e.int_value, e.int_value};
    case ExprKind::Ref:
      if (e.ref != RefKind::Local || e.has_index || e.has_parens) return kFull;
      for (auto it = loops.rbegin(); it != loops.rend(); ++it)
        if (it->name == e.name) return it->range;
      return kFull;
    case ExprKind::Unary:
      if (e.op == Tok::Minus) {
        const IntRange x = range_of(*e.lhs, loops, depth + 1);
        return checked(-x.hi, -x.lo);  // -INT32_MIN saturates: outside int32, so the full range
      }
      return kFull;
    case ExprKind::Binary: {
      const IntRange a = range_of(*e.lhs, loops, depth + 1), b = range_of(*e.rhs, loops, depth + 1);
      switch (e.op) {
        case Tok::Plus:
          return checked(a.lo + b.lo, a.hi + b.hi);  // wraps only outside int32
        case Tok::Minus:
          return checked(a.lo - b.hi, a.hi - b.lo);
        case Tok::Star: {
          const IntRange p = product(a, b);
          return checked(p.lo, p.hi);  // int only when it fits (the checker made it Int then)
        }
        case Tok::Percent: {
          int64_t c = 0;
          if (!constant(*e.rhs, c) || c == 0) return kFull;
          const int64_t m = (c < 0 ? -c : c) - 1;  // the remainder truncates: |r| < |c|, sign of a
          if (e.lhs->type == Kind::Int && a.lo >= 0) return {0, std::min(m, a.hi)};
          return {-m, m};
        }
        case Tok::Amp: {
          int64_t c = 0;
          if ((constant(*e.rhs, c) || constant(*e.lhs, c)) && c >= 0) return {0, c};  // a mask
          return kFull;
        }
        default:
          return kFull;
      }
    }
    default:
      return kFull;
  }
}

bool product_fits(const Expr& a, const Expr& b, const std::vector<LoopRange>& loops) {
  const IntRange p = product(range_of(a, loops, 0), range_of(b, loops, 0));
  return fits(p.lo, p.hi);
}

bool constant_loop_range(const Stmt& s, IntRange& out) {
  int64_t start = 0, end = 0, step = 1;
  if (!s.value || !s.end || !constant(*s.value, start) || !constant(*s.end, end)) return false;
  if (s.step && !constant(*s.step, step)) return false;
  if (step == 0) return false;
  out = {std::min(start, end), std::max(start, end)};
  return true;
}

bool block_assigns(const Block& b, std::string_view name) {
  for (const Stmt* s : b) {
    for (const Expr* t : s->targets)
      if (t->kind == ExprKind::Ref && t->name == name) return true;
    if (block_assigns(s->body, name) || block_assigns(s->handler, name)) return true;
    for (const IfArm& a : s->arms)
      if (block_assigns(a.body, name)) return true;
    for (const SwitchCase& c : s->cases)
      if (block_assigns(c.body, name)) return true;
  }
  return false;
}

}  // namespace uprog::gold
