// Random expression trees over ints and floats, and their reference evaluation.
// The same tree is printed as a Gold command line (gold_text.h) and as uprog assembly (asm_text.h).
#pragma once
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "reference.h"

namespace uprog::differential {

enum class Op {
  IntLit,
  FloatLit,
  IntVar,
  FloatVar,  // leaves
  Neg,
  Not,
  BitNot,
  Abs,
  Sign,
  Fix,
  Rnd,
  Real,
  Sqrt,  // one operand
  Add,
  Sub,
  Mul,
  Div,
  Rem,
  And,
  Or,
  Shl,
  Shr,  // two operands
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  LogAnd,
  LogOr,
};

struct Expr {
  Op op = Op::IntLit;
  Num literal;       // IntLit / FloatLit: the value
  std::string text;  // the literal as written in Gold ("0x80000000", "2.5e3", ...)
  int var = 0;       // IntVar / FloatVar: which of kVars
  std::unique_ptr<Expr> a, b;
};

constexpr int kVars = 4;  // i0..i3 (int) and f0..f3 (float)
struct Vars {
  int32_t i[kVars] = {};
  float f[kVars] = {};
  std::string i_text[kVars], f_text[kVars];  // how the line assigns them
};

// How int * int behaves: Gold promotes to float when the product does not fit (1.5); the
// typed MULI opcode wraps.
enum class IntMul { Promote, Wrap };

Outcome evaluate(const Expr& e, const Vars& vars, IntMul mul);
// Whether the expression is a float whatever the values (the static type a typed code
// generator sees; an int product under Promote is not static).
bool statically_float(const Expr& e);

class Generator {
 public:
  explicit Generator(uint32_t seed) : rng_(seed) {}
  std::unique_ptr<Expr> expression(int depth);
  Vars vars();
  // A literal the Gold lexer reads exactly as the reference does.
  std::unique_ptr<Expr> int_literal();
  std::unique_ptr<Expr> float_literal();
  uint32_t below(uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng_); }

 private:
  int32_t interesting_int();
  std::mt19937 rng_;
};

bool is_leaf(Op op);
bool is_unary(Op op);

}  // namespace uprog::differential
