// The compiler's expressions (2.1's right-hand sides, the built-in functions of 2.3) and
// conditions (2.2.8: states, relations, TOUT, `&`, `|`, `~`). Integers stay integers except
// under `/`, which divides as floats, or into an integer exactly rounded (2.3.6).
#include <cmath>
#include <cstring>

#include "dialects/pdl/compiler.h"
#include "vm/run_error.h"

namespace uprog::pdl {
namespace {

// Binary operators by level, loosest first; `&` and `|` are a condition's own in a condition.
bool op_at_level(std::string_view op, int level, bool in_condition) {
  switch (level) {
    case 0:
      return op == "|" && !in_condition;
    case 1:
      return op == "@";
    case 2:
      return op == "&" && !in_condition;
    case 3:
      return op == "+" || op == "-";
    case 4:
      return op == "*" || op == "/" || op == "%";
    default:
      return false;
  }
}

constexpr int kLevels = 5;

}  // namespace

void Compiler::push_int(int32_t v) {
  if (bytecode::fits_imm(v))
    code_.emit_imm(Op::PUSHI, v);
  else
    code_.emit(Op::PUSHK,
               static_cast<uint32_t>(add_constant(ValueType::Int, static_cast<uint32_t>(v))));
}

void Compiler::push_float(float v) {
  uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  code_.emit(Op::PUSHK, static_cast<uint32_t>(add_constant(ValueType::Float, bits)));
}

int32_t Compiler::add_constant(ValueType type, uint32_t bits) {
  return static_cast<int32_t>(image_.constant_index({type, bits}));
}

uint32_t Compiler::scratch() {
  if (scratch_next_ >= kEntryLocals) {
    error(Error::Syntax, peek().offset, "command too complex");
    return kEntryLocals - 1;
  }
  if (scratch_next_ + 1 > scratch_high_) scratch_high_ = scratch_next_ + 1;
  return scratch_next_++;
}

// Assignment's conversions (2.1): float to an integer rounds, an integer into a short keeps
// its low 16 bits sign-extended; addresses are integers.
void Compiler::convert(Ty from, Ty to, bool to_short) {
  if (is_float(from) && !is_float(to)) code_.emit(Op::F2IR);
  if (!is_float(from) && is_float(to)) code_.emit(Op::I2F);
  if (to_short && !is_float(to)) code_.emit(Op::SEXT, 16);
}

Ty Compiler::int_operand(Ty t, size_t at) {
  if (is_float(t)) {
    error(Error::IntegerNeeded, at);
    code_.emit(Op::F2IR);
  }
  return Ty::Int;
}

Ty Compiler::arith(std::string_view op, Ty a, Ty b, size_t at) {
  ++operations_;
  const bool pa = a == Ty::PtrInt || a == Ty::PtrFloat, pb = b == Ty::PtrInt || b == Ty::PtrFloat;
  if (op == "/") {
    if (integer_quotient_ && !is_float(a) && !is_float(b)) {
      emit_rounded_division();
      return Ty::Int;
    }
    if (!is_float(a)) code_.emit(Op::I2F2);
    if (!is_float(b)) code_.emit(Op::I2F);
    code_.emit(Op::DIVF);
    return Ty::Float;
  }
  if (op == "+" || op == "-" || op == "*") {
    if (is_float(a) || is_float(b)) {
      if (pa || pb) error(Error::IntegerNeeded, at, "pointer arithmetic with a float");
      if (!is_float(a)) code_.emit(Op::I2F2);
      if (!is_float(b)) code_.emit(Op::I2F);
      code_.emit(op == "+" ? Op::ADDF : op == "-" ? Op::SUBF : Op::MULF);
      return Ty::Float;
    }
    code_.emit(op == "+" ? Op::ADDI : op == "-" ? Op::SUBI : Op::MULI);
    if (op == "-" && pa && pb) return Ty::Int;
    if (op != "*" && pa) return a;
    if (op == "+" && pb) return b;
    return Ty::Int;
  }
  if (is_float(a) || is_float(b))
    error(Error::IntegerNeeded, at, "'" + std::string(op) + "' of a float");
  code_.emit(op == "%" ? Op::REMI : op == "&" ? Op::ANDI : op == "|" ? Op::ORI : Op::XORI);
  return Ty::Int;
}

// a -> a / k rounded as emit_rounded_division() rounds, k > 0 a literal: the truncated quotient,
// one more when the remainder reaches (k + 1) / 2, one less when it reaches -(k + 1) / 2 (a
// remainder has the dividend's sign). 13 instructions where the general form takes 39.
void Compiler::emit_rounded_division_by(int32_t k) {
  const int32_t half = k / 2 + k % 2;
  const uint32_t a = scratch();
  code_.emit(Op::STL, a);
  code_.emit(Op::LDL, a);
  push_int(k);
  code_.emit(Op::REMI);
  code_.emit(Op::DUP);
  push_int(half);
  code_.emit(Op::CMPI, bytecode::kRelGe);
  code_.emit(Op::SWAP);
  push_int(-half);
  code_.emit(Op::CMPI, bytecode::kRelLe);
  code_.emit(Op::SUBI);
  code_.emit(Op::LDL, a);
  push_int(k);
  code_.emit(Op::DIVI);
  code_.emit(Op::ADDI);
  release(1);
}

// a b -> a / b rounded to nearest, halves away from zero, as F2IR rounds the float quotient
// (2.3.6: r=p/4 is 3), but exact for every 32-bit a (100000001/1 stays 100000001): the
// truncated quotient, one more away from zero when twice the remainder reaches b (both
// magnitudes unsigned, so that INT_MIN's is exact). b = 0 is DivisionByZero, as for a float.
void Compiler::emit_rounded_division() {
  constexpr uint32_t kCmpGreaterOrEqual = 5;
  const uint32_t a = scratch(), b = scratch(), q = scratch(), r = scratch();
  auto push_magnitude = [&](uint32_t local) {  // (x ^ m) - m, m = x >> 31: |x| as unsigned
    code_.emit(Op::LDL, local);
    code_.emit(Op::LDL, local);
    push_int(31);
    code_.emit(Op::SHRI);
    code_.emit(Op::XORI);
    code_.emit(Op::LDL, local);
    push_int(31);
    code_.emit(Op::SHRI);
    code_.emit(Op::SUBI);
  };
  code_.emit(Op::STL, b);
  code_.emit(Op::STL, a);
  code_.emit(Op::LDL, a);
  code_.emit(Op::LDL, b);
  code_.emit(Op::DIVI);
  code_.emit(Op::STL, q);
  code_.emit(Op::LDL, a);
  code_.emit(Op::LDL, b);
  code_.emit(Op::REMI);
  code_.emit(Op::STL, r);
  push_magnitude(r);
  code_.emit(Op::DUP);
  code_.emit(Op::ADDI);
  push_magnitude(b);
  code_.emit(Op::CMPU, kCmpGreaterOrEqual);
  code_.emit(Op::LDL, a);  // away from zero: +1, or -1 when the signs differ
  code_.emit(Op::LDL, b);
  code_.emit(Op::XORI);
  push_int(31);
  code_.emit(Op::SHRI);
  push_int(1);
  code_.emit(Op::ORI);
  code_.emit(Op::MULI);
  code_.emit(Op::LDL, q);
  code_.emit(Op::ADDI);
  release(4);
}

Ty Compiler::expr(bool in_condition, int level) {
  if (level == kLevels) return unary(in_condition);
  Ty a = expr(in_condition, level + 1);
  while (peek().kind == Tok::Op && op_at_level(peek().text, level, in_condition)) {
    const Token& op = next();
    const Token& divisor = peek();
    if (op.text == "/" && integer_quotient_ && !is_float(a) && divisor.kind == Tok::Int &&
        divisor.int_value > 0 && bytecode::fits_imm(divisor.int_value)) {
      next();  // a literal divisor: known, so never pushed (it is each instruction's immediate)
      ++operations_;
      emit_rounded_division_by(divisor.int_value);
      a = Ty::Int;
      continue;
    }
    const Ty b = expr(in_condition, level + 1);
    a = arith(op.text, a, b, op.offset);
  }
  return a;
}

// Every operand is parsed here, one level deeper for each '(' and unary operator around it: the
// limit keeps the parser's own stack bounded whatever the source (a fuzzer's 10 000 '(').
Ty Compiler::unary(bool in_condition) {
  if (expression_depth_ == 0) expression_abandoned_ = false;
  if (expression_depth_ >= kMaxExpressionDepth) {
    error(Error::ExpressionTooDeep, peek().offset);
    // The rest of the command is skipped up to its ';', and the ')' and ']' the levels still
    // open expect are not reported again (error()).
    expression_abandoned_ = true;
    const size_t from = pos_;
    while (peek().kind != Tok::End && !at_op(";") && !(pos_ != from && peek().line_start)) next();
    push_int(0);
    return Ty::Int;
  }
  ++expression_depth_;
  const Ty ty = operand(in_condition);
  --expression_depth_;
  return ty;
}

Ty Compiler::operand(bool in_condition) {
  const Token& t = peek();
  if (at_op("-")) {
    next();
    if (peek().kind == Tok::Int) {
      push_int(static_cast<int32_t>(0u - static_cast<uint32_t>(next().int_value)));
      return Ty::Int;
    }
    if (peek().kind == Tok::Float) {
      push_float(-next().float_value);
      return Ty::Float;
    }
    ++operations_;
    const Ty a = unary(in_condition);
    code_.emit(is_float(a) ? Op::NEGF : Op::NEGI);
    return is_float(a) ? Ty::Float : Ty::Int;
  }
  if (at_op("~")) {
    next();
    ++operations_;
    int_operand(unary(in_condition), t.offset);
    code_.emit(Op::NOTI);
    return Ty::Int;
  }
  if (at_op("&")) {
    next();
    if (!logical_address(false)) return Ty::Int;
    return address_float_ ? Ty::PtrFloat : Ty::PtrInt;
  }
  return primary(in_condition);
}

Ty Compiler::primary(bool in_condition) {
  const Token& t = peek();
  switch (t.kind) {
    case Tok::Int:
    case Tok::Char:
      next();
      push_int(t.int_value);
      return Ty::Int;
    case Tok::Float:
      next();
      push_float(t.float_value);
      return Ty::Float;
    case Tok::String:
      error(Error::Syntax, t.offset, "a string stands only alone on the right of '='");
      next();
      push_int(0);
      return Ty::Int;
    case Tok::End:
      error(Error::Expected, t.offset, "a value at the end of the file");
      push_int(0);
      return Ty::Int;
    default:
      break;
  }
  if (accept_op("(")) {
    const Ty a = expr(in_condition);
    expect_op(")");
    return a;
  }
  if (at_op("<")) {
    // <STATE> is the state's number (st=<LEFT_LIM>); <label> the slot of the label's command;
    // <var> the state whose number var holds.
    next();
    const bool invert = accept_op("~");
    const Token& name = peek();
    if (name.kind == Tok::Name && find_state(name.text) && !find_var(name.text)) {
      next();
      expect_op(">");
      if (invert) error(Error::Syntax, name.offset, "'~' of a state number");
      push_int(find_state(name.text)->number);
      return Ty::Int;
    }
    if (name.kind == Tok::Name && !invert && !find_var(name.text) && at_op(">", 1)) {
      // <label>: its slot, which a label defined further on gives at the end (compile()).
      next();
      next();
      label_named(name.text, scope_, name.offset);
      image_.constants.push_back({ValueType::Int, 0});
      const auto constant = static_cast<uint32_t>(image_.constants.size() - 1);
      label_values_.push_back({scope_, name.text, constant});
      code_.emit(Op::PUSHK, constant);
      return Ty::Int;
    }
    int_operand(primary(false), name.offset);
    expect_op(">");
    code_.emit(Op::CMDGETX, kStateCommand);
    if (invert) code_.emit(Op::LNOT);
    return Ty::Int;
  }
  if (t.kind == Tok::Name && equal_ignoring_case(t.text, "sttovar")) {
    next();
    condition();
    return Ty::Int;
  }
  if (t.kind == Tok::Name && at_op("(", 1) && is_builtin_function(t.text) && !find_var(t.text)) {
    if (!equal_ignoring_case(t.text, "sizeof")) check_call_alone(pos_);
    next();
    return builtin(t.text, t.offset);
  }
  if (t.kind != Tok::Name && !at_op("*")) {
    error(Error::Syntax, t.offset, "unexpected '" + t.text + "'");
    next();
    push_int(0);
    return Ty::Int;
  }
  std::optional<Place> p = parse_place(false);
  if (!p) {
    push_int(0);
    return Ty::Int;
  }
  emit_load(*p, false);
  Ty type = p->type;
  if (accept_op("->")) {
    // v->n: bit n of v (2.1.3).
    int_operand(type, t.offset);
    ++operations_;
    int_operand(primary(false), t.offset);
    code_.emit(Op::SHRU);
    push_int(1);
    code_.emit(Op::ANDI);
    type = Ty::Int;
  }
  return type;
}

Ty Compiler::builtin(const std::string& raw, size_t at) {
  std::string name;
  for (char c : raw) name.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  ++operations_;
  if (name == "sizeof") {
    expect_op("(");
    const Token& v = next();
    expect_op(")");
    if (const Var* var = find_var(v.text)) {
      push_int(static_cast<int32_t>(var->length));
    } else if (const SystemVariable* s = find_system_variable(v.text)) {
      push_int(static_cast<int32_t>(s->slave ? kMaxAxes : s->length));
    } else {
      error(Error::UnknownName, v.offset, v.text);
      push_int(0);
    }
    return Ty::Int;
  }
  if ((name == "memmin" || name == "memmax" || name == "memsum") && !strict_forms_) {
    error(Error::Syntax, at, raw + " stands alone on the right of '='");
  }
  expect_op("(");
  std::vector<Ty> args;
  std::vector<uint32_t> temps;
  while (!at_op(")") && peek().kind != Tok::End) {
    const size_t first = pos_;
    args.push_back(expr());
    check_function_argument(first, pos_, at_op(")"));
    if (!accept_op(",")) break;
  }
  expect_op(")");
  const size_t want = name == "max" || name == "min" || name == "divi" || name == "shift" ||
                              name == "bitset" || name == "bitclr" || name == "bittog"
                          ? 2
                          : 1;
  if (args.size() != want) {
    error(Error::ArgumentCount, at, raw + " takes " + std::to_string(want));
    for (size_t i = 0; i < args.size(); ++i) code_.emit(Op::POP);
    push_int(0);
    return Ty::Int;
  }
  if (want == 1) {
    const Ty a = args[0];
    if (name == "abs") {
      code_.emit(is_float(a) ? Op::ABSF : Op::ABSI);
      return is_float(a) ? Ty::Float : Ty::Int;
    }
    if (name == "sign") {
      code_.emit(is_float(a) ? Op::SIGNF : Op::SIGNI);
      return Ty::Int;
    }
    if (!is_float(a)) code_.emit(Op::I2F);
    if (name == "sin" || name == "cos") {
      code_.emit(name == "sin" ? Op::SINF : Op::COSF);
      return Ty::Float;
    }
    // sqrt: of a negative number, the negative root (2.3.5).
    const uint32_t s = scratch();
    CodeBuilder::Label pos = code_.new_label(), end = code_.new_label();
    code_.emit(Op::STL, s);
    code_.emit(Op::LDL, s);
    push_float(0.0f);
    code_.emit_to(Op::JNLTF, pos);
    code_.emit(Op::LDL, s);
    code_.emit(Op::NEGF);
    code_.emit(Op::SQRTF);
    code_.emit(Op::NEGF);
    code_.emit_to(Op::JMP, end);
    code_.bind(pos);
    code_.emit(Op::LDL, s);
    code_.emit(Op::SQRTF);
    code_.bind(end);
    release(1);
    return Ty::Float;
  }
  Ty a = args[0], b = args[1];
  if (name == "max" || name == "min") {
    const bool f = is_float(a) || is_float(b);
    if (f && !is_float(a)) code_.emit(Op::I2F2);
    if (f && !is_float(b)) code_.emit(Op::I2F);
    const uint32_t s1 = scratch(), s2 = scratch();
    code_.emit(Op::STL, s2);
    code_.emit(Op::STL, s1);
    CodeBuilder::Label second = code_.new_label(), end = code_.new_label();
    code_.emit(Op::LDL, s1);
    code_.emit(Op::LDL, s2);
    code_.emit(f ? Op::CMPF : Op::CMPI, name == "max" ? bytecode::kRelGe : bytecode::kRelLe);
    code_.emit_to(Op::JZ, second);
    code_.emit(Op::LDL, s1);
    code_.emit_to(Op::JMP, end);
    code_.bind(second);
    code_.emit(Op::LDL, s2);
    code_.bind(end);
    release(2);
    return f ? Ty::Float : Ty::Int;
  }
  if (name == "divi") {
    if (is_float(a) || is_float(b)) {
      if (!is_float(a)) code_.emit(Op::I2F2);
      if (!is_float(b)) code_.emit(Op::I2F);
      code_.emit(Op::DIVF);
      code_.emit(Op::F2IT);
    } else {
      code_.emit(Op::DIVI);
    }
    return Ty::Int;
  }
  if (is_float(a) || is_float(b)) error(Error::IntegerNeeded, at, raw);
  if (name == "shift") {
    // n > 0 shifts left, n < 0 right (arithmetic).
    const uint32_t s1 = scratch(), s2 = scratch();
    code_.emit(Op::STL, s2);
    code_.emit(Op::STL, s1);
    CodeBuilder::Label right = code_.new_label(), end = code_.new_label();
    code_.emit(Op::LDL, s2);
    push_int(0);
    code_.emit_to(Op::JLTI, right);
    code_.emit(Op::LDL, s1);
    code_.emit(Op::LDL, s2);
    code_.emit(Op::SHLI);
    code_.emit_to(Op::JMP, end);
    code_.bind(right);
    code_.emit(Op::LDL, s1);
    code_.emit(Op::LDL, s2);
    code_.emit(Op::NEGI);
    code_.emit(Op::SHRI);
    code_.bind(end);
    release(2);
    return Ty::Int;
  }
  // bitset/bitclr/bittog: a, n on the stack -> a op (1 << n).
  const uint32_t s = scratch();
  code_.emit(Op::STL, s);
  push_int(1);
  code_.emit(Op::LDL, s);
  code_.emit(Op::SHLI);
  release(1);
  if (name == "bitclr") {
    code_.emit(Op::NOTI);
    code_.emit(Op::ANDI);
  } else {
    code_.emit(name == "bitset" ? Op::ORI : Op::XORI);
  }
  return Ty::Int;
}

// --- conditions: each leaves int 0 or 1

void Compiler::condition() {
  cond_and();
  while (accept_op("|")) {
    cond_and();
    code_.emit(Op::ORI);
  }
}

void Compiler::cond_and() {
  cond_not();
  while (accept_op("&")) {
    cond_not();
    code_.emit(Op::ANDI);
  }
}

void Compiler::cond_not() {
  if (accept_op("~")) {
    cond_not();
    code_.emit(Op::LNOT);
    return;
  }
  cond_atom();
}

void Compiler::cond_atom() {
  if (accept_op("(")) {
    condition();
    expect_op(")");
    return;
  }
  if (at_op("<")) {
    // <var>: the state whose number var holds; <STATE>: that state.
    next();
    const bool invert = accept_op("~");
    const Token& name = peek();
    if (name.kind == Tok::Name && find_state(name.text) && !find_var(name.text)) {
      next();
      code_.emit(Op::CMDGET, kStateCommand, static_cast<uint32_t>(find_state(name.text)->number));
    } else {
      int_operand(primary(false), name.offset);
      code_.emit(Op::CMDGETX, kStateCommand);
    }
    expect_op(">");
    if (invert) code_.emit(Op::LNOT);
    return;
  }
  const Token& first = peek();
  const size_t first_pos = pos_;
  const Ty a = expr(true);
  const bool lone_state = pos_ == first_pos + 1 && first.kind == Tok::Name &&
                          find_state(first.text) && !find_var(first.text);
  if (at_word("TOUT")) {
    // v1 TOUT v2: fclk - v1 >= v2 (2.2.11), wrapping.
    const size_t at = next().offset;
    int_operand(a, at);
    code_.emit(Op::CMDGET, 14, 0);
    code_.emit(Op::SWAP);
    code_.emit(Op::SUBI);
    int_operand(expr(true), at);
    code_.emit(Op::CMPI, bytecode::kRelGe);
    return;
  }
  static constexpr std::string_view kRelations[] = {"=", "<>", "<", "<=", ">", ">="};
  for (uint32_t i = 0; i < 6; ++i) {  // in the order of the relations, kRelEq..kRelGe
    if (!at_op(kRelations[i])) continue;
    next();
    const Ty b = expr(true);
    const bool f = is_float(a) || is_float(b);
    if (f && !is_float(a)) code_.emit(Op::I2F2);
    if (f && !is_float(b)) code_.emit(Op::I2F);
    code_.emit(f ? Op::CMPF : Op::CMPI, i);
    return;
  }
  if (lone_state) return;  // already 0 or 1
  if (is_float(a)) {
    code_.emit(Op::TRUTHF);
  } else {
    push_int(0);
    code_.emit(Op::CMPI, bytecode::kRelNe);
  }
}

}  // namespace uprog::pdl
