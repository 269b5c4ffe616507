// uprog assembly of an expression tree: constants for every literal that PUSHI cannot hold,
// the variables as globals set at the start of main.
#include "asm_text.h"

#include <cstdlib>
#include <cstring>
#include <sstream>

#include "bytecode/opcodes.h"

namespace uprog::differential {

namespace {

class Lowering {
 public:
  Lowering(const Vars& vars, AsmStyle style) : vars_(vars), style_(style) {}

  std::string program(const Expr& e) {
    for (int k = 0; k < kVars; ++k) {
      push_int(vars_.i[k]);
      code_ << "  STG i" << k << "\n";
      push_float(vars_.f[k]);
      code_ << "  STG f" << k << "\n";
    }
    if (style_ == AsmStyle::Typed) {
      const bool is_float = typed(e);
      code_ << "  STG " << (is_float ? "rf" : "ri") << "\n";
    } else {
      pairs(e);
      code_ << "  STG rt\n  STG rv\n";
    }
    code_ << "  RET\n";
    std::ostringstream s;
    s << ".source \"differential.s\"\n";
    for (int k = 0; k < kVars; ++k)
      s << ".global int \"i" << k << "\" 1\n.global float \"f" << k << "\" 1\n";
    s << ".global int \"ri\" 1\n.global float \"rf\" 1\n.global int \"rv\" 1\n.global int \"rt\" "
         "1\n";
    s << consts_.str() << ".routine function \"main\" in=0 out=0 entry=main\nmain:\n"
      << code_.str();
    return s.str();
  }

 private:
  void push_int(int32_t v) {
    if (bytecode::fits_imm(v)) {
      code_ << "  PUSHI " << v << "\n";
    } else {
      consts_ << ".const int " << v << "\n";
      code_ << "  PUSHK " << const_count_++ << "\n";
    }
  }
  void push_float(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    consts_ << ".const float bits 0x" << std::hex << bits << std::dec << "\n";
    code_ << "  PUSHK " << const_count_++ << "\n";
  }
  void emit(const char* op) { code_ << "  " << op << "\n"; }

  // Typed style: returns whether the value left on the stack is a float.
  bool typed(const Expr& e) {
    switch (e.op) {
      case Op::IntLit:
        push_int(e.literal.i);
        return false;
      case Op::FloatLit:
        push_float(e.literal.f);
        return true;
      case Op::IntVar:
        code_ << "  LDG i" << e.var << "\n";
        return false;
      case Op::FloatVar:
        code_ << "  LDG f" << e.var << "\n";
        return true;
      default:
        break;
    }
    if (is_unary(e.op)) {
      const bool f = typed(*e.a);
      switch (e.op) {
        case Op::Neg:
          emit(f ? "NEGF" : "NEGI");
          return f;
        case Op::Abs:
          emit(f ? "ABSF" : "ABSI");
          return f;
        case Op::Sign:
          emit(f ? "SIGNF" : "SIGNI");
          return false;
        case Op::Fix:
          if (f) emit("F2IT");
          return false;
        case Op::Rnd:
          if (f) emit("F2IR");
          return false;
        case Op::Real:
          if (!f) emit("I2F");
          return true;
        case Op::Sqrt:
          if (!f) emit("I2F");
          emit("SQRTF");
          return true;
        case Op::Not:
          if (f) emit("F2IT");
          emit("LNOT");
          return false;
        default:
          if (f) emit("F2IT");
          emit("NOTI");
          return false;  // BitNot
      }
    }
    switch (e.op) {
      case Op::Rem:
      case Op::And:
      case Op::Or:
      case Op::Shl:
      case Op::Shr: {
        if (typed(*e.a)) emit("F2IT");
        if (typed(*e.b)) emit("F2IT");
        static const char* const kOps[] = {"REMI", "ANDI", "ORI", "SHLI", "SHRI"};
        emit(kOps[static_cast<int>(e.op) - static_cast<int>(Op::Rem)]);
        return false;
      }
      case Op::LogAnd:
      case Op::LogOr:
        truth_typed(*e.a);
        truth_typed(*e.b);
        emit(e.op == Op::LogAnd ? "ANDI" : "ORI");
        return false;
      default:
        break;
    }
    // Arithmetic and comparisons: an int beside a float becomes a float.
    const bool fa = typed(*e.a), fb = typed(*e.b);
    const bool f = fa || fb;
    if (f && !fa) emit("I2F2");
    if (f && !fb) emit("I2F");
    static const char* const kInt[] = {"ADDI", "SUBI", "MULI", "DIVI"};
    static const char* const kFloat[] = {"ADDF", "SUBF", "MULF", "DIVF"};
    static const char* const kCmpInt[] = {"CMPI 2", "CMPI 3", "CMPI 4",
                                          "CMPI 5", "CMPI 0", "CMPI 1"};
    static const char* const kCmpFloat[] = {"CMPF 2", "CMPF 3", "CMPF 4",
                                            "CMPF 5", "CMPF 0", "CMPF 1"};
    if (e.op <= Op::Div) {
      emit((f ? kFloat : kInt)[static_cast<int>(e.op) - static_cast<int>(Op::Add)]);
      return f;
    }
    emit((f ? kCmpFloat : kCmpInt)[static_cast<int>(e.op) - static_cast<int>(Op::Lt)]);
    return false;
  }
  void truth_typed(const Expr& e) {
    if (typed(e)) {
      emit("TRUTHF");
    } else {
      emit("PUSHI 0");
      emit("CMPI 1");
    }
  }

  // Pairs style: every value is [value, tag].
  void pairs(const Expr& e) {
    switch (e.op) {
      case Op::IntLit:
        push_int(e.literal.i);
        emit("I2D");
        return;
      case Op::FloatLit:
        push_float(e.literal.f);
        emit("F2D");
        return;
      case Op::IntVar:
        code_ << "  LDG i" << e.var << "\n";
        emit("I2D");
        return;
      case Op::FloatVar:
        code_ << "  LDG f" << e.var << "\n";
        emit("F2D");
        return;
      default:
        break;
    }
    if (is_unary(e.op)) {
      pairs(*e.a);
      switch (e.op) {
        case Op::Neg:
          emit("NEGD");
          return;
        case Op::Abs:
          emit("ABSD");
          return;
        case Op::Sign:
          emit("D2F");
          emit("SIGNF");
          emit("I2D");
          return;
        case Op::Fix:
          emit("D2IT");
          emit("I2D");
          return;
        case Op::Rnd:
          emit("D2IR");
          emit("I2D");
          return;
        case Op::Real:
          emit("D2F");
          emit("F2D");
          return;
        case Op::Sqrt:
          emit("D2F");
          emit("SQRTF");
          emit("F2D");
          return;
        case Op::Not:
          emit("D2IT");
          emit("LNOT");
          emit("I2D");
          return;
        default:
          emit("D2IT");
          emit("NOTI");
          emit("I2D");
          return;
      }
    }
    switch (e.op) {
      case Op::Rem:
      case Op::And:
      case Op::Or:
      case Op::Shl:
      case Op::Shr: {
        pairs(*e.a);
        emit("D2IT");
        pairs(*e.b);
        emit("D2IT");
        static const char* const kOps[] = {"REMI", "ANDI", "ORI", "SHLI", "SHRI"};
        emit(kOps[static_cast<int>(e.op) - static_cast<int>(Op::Rem)]);
        emit("I2D");
        return;
      }
      case Op::LogAnd:
      case Op::LogOr:
        pairs(*e.a);
        emit("D2F");
        emit("TRUTHF");
        pairs(*e.b);
        emit("D2F");
        emit("TRUTHF");
        emit(e.op == Op::LogAnd ? "ANDI" : "ORI");
        emit("I2D");
        return;
      default:
        break;
    }
    pairs(*e.a);
    pairs(*e.b);
    static const char* const kArith[] = {"ADDD", "SUBD", "MULD", "DIVD"};
    static const int kCmp[] = {2, 3, 4, 5, 0, 1};  // CMPD's A: 0 ==, 1 !=, 2 <, 3 <=, 4 >, 5 >=
    if (e.op <= Op::Div) {
      emit(kArith[static_cast<int>(e.op) - static_cast<int>(Op::Add)]);
      return;
    }
    code_ << "  CMPD " << kCmp[static_cast<int>(e.op) - static_cast<int>(Op::Lt)] << "\n";
    emit("I2D");
  }

  const Vars& vars_;
  AsmStyle style_;
  std::ostringstream code_, consts_;
  int const_count_ = 0;
};

}  // namespace

std::string asm_program(const Expr& e, const Vars& vars, AsmStyle style) {
  return Lowering(vars, style).program(e);
}

}  // namespace uprog::differential
