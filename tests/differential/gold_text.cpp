// Gold text of an expression tree: binary operators are left-associative; a child is
// parenthesised when it binds less tightly than its parent (manual 1.4's precedence levels).
#include "gold_text.h"

#include <cstdlib>

namespace uprog::differential {

namespace {

int precedence(Op op) {
  switch (op) {
    case Op::Mul:
    case Op::Div:
    case Op::Rem:
      return 16;
    case Op::Add:
    case Op::Sub:
      return 15;
    case Op::Shl:
    case Op::Shr:
      return 14;
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
      return 13;
    case Op::Eq:
    case Op::Ne:
      return 12;
    case Op::And:
      return 11;
    case Op::Or:
      return 9;
    case Op::LogAnd:
      return 8;
    case Op::LogOr:
      return 7;
    default:
      return 100;  // leaves, unary operators and function calls
  }
}

const char* symbol(Op op) {
  switch (op) {
    case Op::Add:
      return "+";
    case Op::Sub:
      return "-";
    case Op::Mul:
      return "*";
    case Op::Div:
      return "/";
    case Op::Rem:
      return "%";
    case Op::And:
      return "&";
    case Op::Or:
      return "|";
    case Op::Shl:
      return "<<";
    case Op::Shr:
      return ">>";
    case Op::Lt:
      return "<";
    case Op::Le:
      return "<=";
    case Op::Gt:
      return ">";
    case Op::Ge:
      return ">=";
    case Op::Eq:
      return "==";
    case Op::Ne:
      return "!=";
    case Op::LogAnd:
      return "&&";
    case Op::LogOr:
      return "||";
    case Op::Neg:
      return "-";
    case Op::Not:
      return "!";
    case Op::BitNot:
      return "~";
    case Op::Abs:
      return "abs";
    case Op::Sign:
      return "sign";
    case Op::Fix:
      return "fix";
    case Op::Rnd:
      return "rnd";
    case Op::Real:
      return "real";
    case Op::Sqrt:
      return "sqrt";
    default:
      std::abort();
  }
}

class Printer {
 public:
  explicit Printer(uint32_t seed) : state_(seed | 1u) {}

  std::string text(const Expr& e) {
    switch (e.op) {
      case Op::IntLit:
      case Op::FloatLit:
        return e.text;
      case Op::IntVar:
        return "i" + std::to_string(e.var);
      case Op::FloatVar:
        return "f" + std::to_string(e.var);
      case Op::Neg:
      case Op::Not:
      case Op::BitNot:
        // Always "(-x)": never "--", and no question of how "a*-b" binds.
        return std::string("(") + symbol(e.op) + child(*e.a, 100) + ")";
      default:
        break;
    }
    if (is_unary(e.op)) return std::string(symbol(e.op)) + "(" + text(*e.a) + ")";
    const int p = precedence(e.op);
    return child(*e.a, p) + " " + symbol(e.op) + " " + child(*e.b, p + 1);
  }

 private:
  // A child needs parentheses when it binds less tightly than `min`.
  std::string child(const Expr& e, int min) {
    const std::string t = text(e);
    if (precedence(e.op) < min || (!is_leaf(e.op) && next() % 4 == 0)) return "(" + t + ")";
    return t;
  }
  uint32_t next() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 17;
    state_ ^= state_ << 5;
    return state_;
  }
  uint32_t state_;
};

}  // namespace

std::string gold_text(const Expr& e, uint32_t noise_seed) { return Printer(noise_seed).text(e); }

std::string gold_assignments(const Vars& vars) {
  std::string s;
  for (int k = 0; k < kVars; ++k) {
    s += "i" + std::to_string(k) + "=" + vars.i_text[k] + "; ";
    s += "f" + std::to_string(k) + "=" + vars.f_text[k] + "; ";
  }
  return s;
}

}  // namespace uprog::differential
