// The Gold code generator.
#include "dialects/gold/codegen.h"

#include <cstring>
#include <functional>
#include <map>
#include <unordered_map>

#include "bytecode/code_builder.h"
#include "dialects/gold/builtins.h"
#include "dialects/gold/commands.h"
#include "dialects/gold/keywords.h"
#include "support/arith.h"

namespace uprog::gold {

namespace {

using bytecode::CodeBuilder;
using bytecode::Op;

// run_errors.def: "for loop step is zero" (the manual's INFINITE_LOOP, 2.12.2).
constexpr uint32_t kZeroForStep = 5;
constexpr uint32_t kOverflow = 16;  // vm/run_errors.def: "result out of range"
constexpr uint32_t kMicrosecondsPerMs = 1000;

ValueType value_type(VarType t) { return t == VarType::Int ? ValueType::Int : ValueType::Float; }
Kind operand_kind(Kind k) { return k == Kind::None ? Kind::Int : k; }

class Gen {
 public:
  Gen(bytecode::Image& image, const Symbols* symbols, const Locator& locator,
      ConstantTable& constants)
      : img_(image), cb_(image.code), syms_(symbols), loc_(locator), constants_(constants) {}

  // ---- routines

  void begin_routine(std::vector<bytecode::Local>* locals) {
    locals_ = locals;
    temp_base_ = locals->size();
    temp_top_ = temp_base_;
    goto_labels_.clear();
    loops_.clear();
    try_depth_ = 0;
  }

  void declare_goto_labels(const Block& b) {
    for (const StmtPtr& s : b)
      if (s->kind == StmtKind::Label)
        goto_labels_[label_key(s->name, s->auto_label)] = cb_.new_label();
  }

  void block(const Block& b) {
    for (const StmtPtr& s : b) statement(*s);
  }

  bool finish() { return cb_.finish(); }
  uint32_t here() const { return cb_.here(); }
  void emit(Op op, uint32_t a = 0, uint32_t b = 0) { cb_.emit(op, a, b); }
  void line_entry(uint32_t offset) {
    if (!with_lines) return;  // a check needs no line table
    const Location where = loc_.locate(offset);
    const uint32_t line = static_cast<uint32_t>(where.line);
    if (!img_.lines.empty() && img_.lines.back().line == line &&
        img_.lines.back().file == where.file)
      return;
    if (!img_.lines.empty() && img_.lines.back().code == cb_.here()) {
      img_.lines.back().line = line;
      img_.lines.back().file = where.file;
      return;
    }
    img_.lines.push_back({cb_.here(), where.file, line});
  }
  void bind_label_stmt(const Stmt& s) {
    auto it = goto_labels_.find(label_key(s.name, s.auto_label));
    if (it != goto_labels_.end() && !cb_.bound(it->second)) cb_.bind(it->second);
  }

  bool with_lines = true;
  // Set for a function's code on its own: routine numbers are known only when the program is
  // put together, so CALL and RESET operands are left for the driver to fill in.
  std::vector<RoutineFixup>* fixups = nullptr;
  std::function<void(const Expr&)> show;     // the command line's way to show a bare value
  std::vector<int32_t> routine_of_function;  // function symbol -> routine index
  std::unordered_map<std::string, int32_t> routine_of_label;  // top-level labels

  // ---- values

  void push_int(int32_t v) {
    if (bytecode::fits_imm(v))
      cb_.emit_imm(Op::PUSHI, v);
    else
      emit(Op::PUSHK, constant(ValueType::Int, static_cast<uint32_t>(v)));
  }
  void push_float(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    emit(Op::PUSHK, constant(ValueType::Float, bits));
  }

  // Converts the value on top of the stack. `round`: float to int rounds (assignments, 1.10)
  // rather than truncates (bitwise operands, fix, 1.5).
  void convert(Kind from, Kind to, bool round = true) {
    from = operand_kind(from);
    if (from == to || to == Kind::None) return;
    switch (to) {
      case Kind::Int:
        if (from == Kind::Float)
          emit(round ? Op::F2IR : Op::F2IT);
        else
          emit(round ? Op::D2IR : Op::D2IT);
        return;
      case Kind::Float:
        emit(from == Kind::Int ? Op::I2F : Op::D2F);
        return;
      case Kind::Dynamic:
        emit(from == Kind::Int ? Op::I2D : Op::F2D);
        return;
      case Kind::None:
        return;
    }
  }

  void value(const Expr& e, Kind want, bool round = true) {
    value(e);
    convert(e.type, want, round);
  }

  // A comparison, `!`, && or ||: an int 0 or 1 already.
  static bool yields_truth(const Expr& e) {
    if (e.kind == ExprKind::Unary) return e.op == Tok::Bang;
    if (e.kind != ExprKind::Binary) return false;
    switch (e.op) {
      case Tok::Lt:
      case Tok::Le:
      case Tok::Gt:
      case Tok::Ge:
      case Tok::EqEq:
      case Tok::Ne:
      case Tok::AndAnd:
      case Tok::OrOr:
        return true;
      default:
        return false;
    }
  }

  // Whether evaluating `e` shows nothing but its value: literals and variables, compared and
  // combined with `!`, && and || (none of them raises an error: conversions saturate). A call,
  // a command or an index (its range error) shows. Both sides of && and || are evaluated
  // (docs/dialects/gold.md, decision 4); a condition may skip a side that shows nothing.
  static bool shows_nothing(const Expr& e) {
    switch (e.kind) {
      case ExprKind::IntLit:
      case ExprKind::FloatLit:
        return true;
      case ExprKind::Ref:
        return (e.ref == RefKind::Local || e.ref == RefKind::Global) && !e.has_index &&
               !e.has_parens;
      case ExprKind::Unary:
        return e.op == Tok::Bang && shows_nothing(*e.lhs);
      case ExprKind::Binary:
        return yields_truth(e) && shows_nothing(*e.lhs) && shows_nothing(*e.rhs);
      default:
        return false;
    }
  }

  // Leaves int 0 or 1: whether the value is not zero.
  void truth(const Expr& e) {
    value(e);
    if (yields_truth(e)) return;
    switch (operand_kind(e.type)) {
      case Kind::Int:
        push_int(0);
        emit(Op::CMPI, bytecode::kRelNe);
        return;
      case Kind::Float:
        emit(Op::TRUTHF);
        return;
      default:
        emit(Op::D2F);
        emit(Op::TRUTHF);
        return;
    }
  }

  // Jumps to `target` when the condition is false (JZ) or true (JNZ): an int is its own truth.
  // && and || whose right side shows nothing jump on each side: as Lua's conditions do, one
  // compare-and-jump a side instead of both truths, their AND or OR, and a jump.
  void branch(const Expr& e, Op jump, CodeBuilder::Label target) {
    // `!` of an int is the opposite jump (of a float it is not: `!0.0004` is 1, 1.6).
    if (e.kind == ExprKind::Unary && e.op == Tok::Bang && operand_kind(e.lhs->type) == Kind::Int)
      return branch(*e.lhs, jump == Op::JZ ? Op::JNZ : Op::JZ, target);
    if (e.kind == ExprKind::Binary && (e.op == Tok::AndAnd || e.op == Tok::OrOr) &&
        shows_nothing(*e.rhs)) {
      if ((e.op == Tok::AndAnd) == (jump == Op::JZ)) {  // either side false (&&), true (||)
        branch(*e.lhs, jump, target);
        branch(*e.rhs, jump, target);
      } else {  // the right side decides once the left is true (&&) or false (||)
        const CodeBuilder::Label past = cb_.new_label();
        branch(*e.lhs, jump == Op::JZ ? Op::JNZ : Op::JZ, past);
        branch(*e.rhs, jump, target);
        cb_.bind(past);
      }
      return;
    }
    value(e);
    switch (operand_kind(e.type)) {
      case Kind::Int:
        break;
      case Kind::Float:
        emit(Op::TRUTHF);
        break;
      default:
        emit(Op::D2F);
        emit(Op::TRUTHF);
        break;
    }
    cb_.emit_to(jump, target);
  }
  void branch_false(const Expr& e, CodeBuilder::Label target) { branch(e, Op::JZ, target); }

  void value(const Expr& e) {
    switch (e.kind) {
      case ExprKind::IntLit:
        push_int(e.int_value);
        return;
      case ExprKind::FloatLit:
        push_float(e.float_value);
        return;
      case ExprKind::Nargout:
        emit(Op::NARGOUT);
        return;
      case ExprKind::Unary:
        unary(e);
        return;
      case ExprKind::Binary:
        binary(e);
        return;
      case ExprKind::Ref:
        ref(e);
        return;
    }
  }

  void unary(const Expr& e) {
    const Kind k = operand_kind(e.lhs->type);
    switch (e.op) {
      case Tok::Minus:
        // A negative literal (`-1.0`) is a constant of its own, as NEGI/NEGF would make it.
        if (e.lhs->kind == ExprKind::FloatLit && k == Kind::Float)
          return push_float(-e.lhs->float_value);
        if (e.lhs->kind == ExprKind::IntLit && k == Kind::Int)
          return push_int(arith::saturating_neg(e.lhs->int_value));
        value(*e.lhs);
        emit(k == Kind::Int ? Op::NEGI : k == Kind::Float ? Op::NEGF : Op::NEGD);
        return;
      case Tok::Bang:  // arguments are truncated to integers (1.6)
        value(*e.lhs, Kind::Int, false);
        emit(Op::LNOT);
        return;
      default:
        value(*e.lhs, Kind::Int, false);
        emit(Op::NOTI);
        return;
    }
  }

  void binary(const Expr& e) {
    const Kind a = operand_kind(e.lhs->type), b = operand_kind(e.rhs->type);
    switch (e.op) {
      case Tok::Plus:
      case Tok::Minus:
      case Tok::Slash: {
        const Kind r = e.type;
        value(*e.lhs, r);
        value(*e.rhs, r);
        static constexpr Op kOps[3][3] = {{Op::ADDI, Op::SUBI, Op::DIVI},
                                          {Op::ADDF, Op::SUBF, Op::DIVF},
                                          {Op::ADDD, Op::SUBD, Op::DIVD}};
        const int col = e.op == Tok::Plus ? 0 : e.op == Tok::Minus ? 1 : 2;
        emit(kOps[r == Kind::Int ? 0 : r == Kind::Float ? 1 : 2][col]);
        return;
      }
      case Tok::Star:
        if (e.type == Kind::Float) {
          value(*e.lhs, Kind::Float);
          value(*e.rhs, Kind::Float);
          emit(Op::MULF);
        } else if (e.type == Kind::Int) {  // the checker proved the product fits (ranges.h)
          value(*e.lhs, Kind::Int);
          value(*e.rhs, Kind::Int);
          emit(Op::MULI);
        } else if (a == Kind::Int && b == Kind::Int) {
          value(*e.lhs);
          value(*e.rhs);
          emit(Op::MULID);
        } else {
          value(*e.lhs, Kind::Dynamic);
          value(*e.rhs, Kind::Dynamic);
          emit(Op::MULD);
        }
        return;
      case Tok::Percent:
      case Tok::Amp:
      case Tok::Pipe:
      case Tok::Shl:
      case Tok::Shr: {
        value(*e.lhs, Kind::Int, false);
        value(*e.rhs, Kind::Int, false);
        emit(e.op == Tok::Percent ? Op::REMI
             : e.op == Tok::Amp   ? Op::ANDI
             : e.op == Tok::Pipe  ? Op::ORI
             : e.op == Tok::Shl   ? Op::SHLI
                                  : Op::SHRI);
        return;
      }
      case Tok::AndAnd:
      case Tok::OrOr:
        // Both sides are evaluated; a float is true when it is not zero (1.6: 0.21&&2 is 1).
        truth(*e.lhs);
        truth(*e.rhs);
        emit(e.op == Tok::AndAnd ? Op::ANDI : Op::ORI);
        return;
      default:
        compare(e.op, *e.lhs, *e.rhs);
        return;
    }
  }

  void compare(Tok op, const Expr& l, const Expr& r) {
    const Kind a = operand_kind(l.type), b = operand_kind(r.type);
    const Kind k = (a == Kind::Float || b == Kind::Float)       ? Kind::Float
                   : (a == Kind::Dynamic || b == Kind::Dynamic) ? Kind::Dynamic
                                                                : Kind::Int;
    value(l, k);
    value(r, k);
    int how = 0;
    switch (op) {
      case Tok::EqEq:
        how = 0;
        break;
      case Tok::Ne:
        how = 1;
        break;
      case Tok::Lt:
        how = 2;
        break;
      case Tok::Le:
        how = 3;
        break;
      case Tok::Gt:
        how = 4;
        break;
      default:
        how = 5;
        break;
    }
    if (k == Kind::Dynamic) {
      emit(Op::CMPD, static_cast<uint32_t>(how));
      return;
    }
    if (k == Kind::Float && how <= 1)
      float_equality(how == 0);
    else
      emit(k == Kind::Int ? Op::CMPI : Op::CMPF, static_cast<uint32_t>(how));
  }

  // Float == (or !=) at the manual's precision (1.3.2: 25000.001 == 25000 is true, 25000.01 ==
  // 25000 false; 2.11.1, 2.11.3: 4 digits after the point compare fine): the two floats on the
  // stack are equal when |a - b| <= 1e-7 * (|a| + |b| + 1) (docs/dialects/gold.md, decision 41).
  void float_equality(bool equal) {
    const uint32_t b = temp(ValueType::Float), a = temp(ValueType::Float);
    emit(Op::STL, b);
    emit(Op::STL, a);
    emit(Op::LDL, a);
    emit(Op::LDL, b);
    emit(Op::SUBF);
    emit(Op::ABSF);
    emit(Op::LDL, a);
    emit(Op::ABSF);
    emit(Op::LDL, b);
    emit(Op::ABSF);
    emit(Op::ADDF);
    push_float(1.0f);
    emit(Op::ADDF);
    push_float(1e-7f);
    emit(Op::MULF);
    emit(Op::CMPF, equal ? bytecode::kRelLe : bytecode::kRelGt);
  }

  // A variable's index as an int; a scalar indexed [0] needs none.
  bool index_of(const Expr& e) {
    if (!e.has_index && !(e.has_parens && e.args.size() == 1)) return false;
    value(*e.args[0], Kind::Int, false);
    return true;
  }

  void ref(const Expr& e) {
    switch (e.ref) {
      case RefKind::Local:
        emit(Op::LDL, static_cast<uint32_t>(e.slot));
        return;
      case RefKind::Global:
        if (scalar_zero_index(e))
          emit(Op::LDG, static_cast<uint32_t>(e.slot));
        else if (index_of(e))
          emit(Op::LDGX, static_cast<uint32_t>(e.slot));
        else
          emit(Op::LDG, static_cast<uint32_t>(e.slot));
        return;
      case RefKind::Command: {
        int32_t k = 0;
        if (e.has_index && e.args[0]->kind == ExprKind::IntLit) {
          k = e.args[0]->int_value;
          emit(Op::CMDGET, e.command->id, static_cast<uint32_t>(k));
        } else if (e.has_index) {
          value(*e.args[0], Kind::Int, false);
          emit(Op::CMDGETX, e.command->id);
        } else {
          emit(Op::CMDGET, e.command->id, 0);
        }
        return;
      }
      case RefKind::Function:
        call(e, 1);
        return;
      case RefKind::Builtin:
        builtin(e);
        return;
      default:
        push_int(0);
        return;
    }
  }

  bool scalar_zero_index(const Expr& e) const {
    if (!e.has_index && !e.has_parens) return true;
    const GlobalSym* g =
        e.ref == RefKind::Global ? &(*globals_)[static_cast<size_t>(e.slot)] : nullptr;
    return g != nullptr && g->length == 0 && e.args.size() == 1 &&
           e.args[0]->kind == ExprKind::IntLit && e.args[0]->int_value == 0;
  }
  const std::vector<GlobalSym>* globals_ = nullptr;

  void call(const Expr& e, uint32_t nargout) {
    const FunctionSym& f = syms_->functions[static_cast<size_t>(e.slot)];
    for (size_t i = 0; i < e.args.size() && i < f.inputs; ++i)
      value(*e.args[i], kind_of(f.def->inputs[i].type));
    if (fixups) {
      fixups->push_back({here(), e.name});
      emit(Op::CALL, 0, nargout);
      return;
    }
    const int32_t routine = routine_of_function[static_cast<size_t>(e.slot)];
    emit(Op::CALL, static_cast<uint32_t>(routine < 0 ? 0 : routine), nargout);
  }

  void builtin(const Expr& e) {
    const Expr& x = *e.args[0];
    const Kind k = operand_kind(x.type);
    switch (e.builtin) {
      case Builtin::Sin:
        value(x, Kind::Float);
        emit(Op::SINF);
        return;
      case Builtin::Cos:
        value(x, Kind::Float);
        emit(Op::COSF);
        return;
      case Builtin::Sqrt:
        value(x, Kind::Float);
        emit(Op::SQRTF);
        return;
      case Builtin::Real:
        value(x, Kind::Float);
        return;
      case Builtin::Abs:
        value(x);
        emit(k == Kind::Int ? Op::ABSI : k == Kind::Float ? Op::ABSF : Op::ABSD);
        return;
      case Builtin::Fix:
        value(x, Kind::Int, false);
        return;
      case Builtin::Rnd:
        value(x, Kind::Int, true);
        return;
      case Builtin::Sign:
        if (k == Kind::Int) {
          value(x);
          emit(Op::SIGNI);
        } else {
          value(x, Kind::Float);
          emit(Op::SIGNF);
        }
        return;
      case Builtin::Prgerr:
        value(x);
        drop(k);
        emit(Op::ERRCODE);
        return;
      case Builtin::Utick:
        value(x);
        drop(k);
        emit(Op::CLOCK);
        return;
      case Builtin::Tick:
        value(x);
        drop(k);
        milliseconds();
        return;
      case Builtin::Utock:
        value(x, Kind::Int, false);
        emit(Op::CLOCK);
        emit(Op::SWAP);
        emit(Op::SUBI);
        return;
      case Builtin::Tock:
        value(x, Kind::Int, false);
        milliseconds();
        emit(Op::SWAP);
        emit(Op::SUBI);
        return;
      case Builtin::Tdif: {
        // Milliseconds since TM was sampled into x (1.12).
        value(x, Kind::Int, false);
        if (const CommandInfo* tm = find_command("TM"))
          emit(Op::CMDGET, tm->id, 0);
        else
          emit(Op::CLOCK);
        emit(Op::SWAP);
        emit(Op::SUBI);
        push_int(static_cast<int32_t>(kMicrosecondsPerMs));
        emit(Op::DIVI);
        return;
      }
    }
  }

  // The clock in milliseconds as an unsigned count, so it does not turn negative halfway.
  void milliseconds() {
    emit(Op::CLOCK);
    push_int(3);
    emit(Op::SHRI);
    push_int(0x1FFFFFFF);
    emit(Op::ANDI);
    push_int(125);
    emit(Op::DIVI);
  }

  void drop(Kind k) {
    emit(Op::POP);
    if (k == Kind::Dynamic) emit(Op::POP);
  }

  // ---- stores

  Kind target_kind(const Expr& t) const {
    switch (t.ref) {
      case RefKind::Local:
        return kind_of((*locals_)[static_cast<size_t>(t.slot)].type);
      case RefKind::Global:
        return kind_of((*globals_)[static_cast<size_t>(t.slot)].type);
      case RefKind::Command:
        return kind_of(t.command->type);
      default:
        return Kind::Int;
    }
  }

  // Pushes what a store needs before the value (an index); returns how to store afterwards.
  enum class StoreHow { Local, Global, GlobalIndexed, Command, CommandIndexed, Drop };
  StoreHow store_prefix(const Expr& t) {
    switch (t.ref) {
      case RefKind::Local:
        return StoreHow::Local;
      case RefKind::Global:
        if (scalar_zero_index(t)) return StoreHow::Global;
        return index_of(t) ? StoreHow::GlobalIndexed : StoreHow::Global;
      case RefKind::Command:
        if (t.has_index && t.args[0]->kind != ExprKind::IntLit) {
          value(*t.args[0], Kind::Int, false);
          return StoreHow::CommandIndexed;
        }
        return StoreHow::Command;
      default:
        return StoreHow::Drop;
    }
  }
  void store(const Expr& t, StoreHow how) {
    switch (how) {
      case StoreHow::Local:
        emit(Op::STL, static_cast<uint32_t>(t.slot));
        return;
      case StoreHow::Global:
        emit(Op::STG, static_cast<uint32_t>(t.slot));
        return;
      case StoreHow::GlobalIndexed:
        emit(Op::STGX, static_cast<uint32_t>(t.slot));
        return;
      case StoreHow::Command:
        emit(Op::CMDSET, t.command->id,
             t.has_index ? static_cast<uint32_t>(t.args[0]->int_value) : 0u);
        return;
      case StoreHow::CommandIndexed:
        emit(Op::CMDSETX, t.command->id);
        return;
      case StoreHow::Drop:
        emit(Op::POP);
        return;
    }
  }

  void assign(const Expr& target, const Expr& v) {
    const StoreHow how = store_prefix(target);
    const Kind want = target_kind(target);
    const Kind have = operand_kind(v.type);
    if (may_leave_float_range(v) && (have == Kind::Float || want == Kind::Float)) {
      value(v, have == Kind::Float ? Kind::Float : want);
      check_float_range();
      convert(Kind::Float, want);
    } else {
      value(v, want);
    }
    store(target, how);
  }

  // Float arithmetic at the top of a value (through unary minus): what can leave the float
  // range. Everything else that is stored was checked when it was stored, is a literal (the
  // lexer refuses 1e37), a drive command or a bounded built-in.
  static bool may_leave_float_range(const Expr& e) {
    if (e.kind == ExprKind::Unary) return e.op == Tok::Minus && may_leave_float_range(*e.lhs);
    if (e.kind != ExprKind::Binary || operand_kind(e.type) == Kind::Int) return false;
    return e.op == Tok::Plus || e.op == Tok::Minus || e.op == Tok::Star || e.op == Tok::Slash;
  }

  // 1.3.2: "If a floating-point number exceeds the floating-point range [-1e37 < N < 1e37], it
  // is also interpreted as an error": the float on top must lie inside, or the thread stops with
  // "result out of range" before the store (NaN, from an inf inside the expression, too).
  void check_float_range() {
    const auto ok = cb_.new_label();
    emit(Op::DUP);
    emit(Op::ABSF);
    push_float(1e37f);
    emit(Op::CMPF, bytecode::kRelLt);
    cb_.emit_to(Op::JNZ, ok);
    emit(Op::RAISE, kOverflow);
    cb_.bind(ok);
  }

  uint32_t temp(ValueType type) {
    const uint32_t slot = static_cast<uint32_t>(temp_top_++);
    if (locals_->size() < temp_top_)
      locals_->push_back({"$t" + std::to_string(slot - temp_base_), type});
    return slot;
  }

  // ---- statements

  void eol(const Stmt& s) {
    if (s.ends_line) emit(Op::EOL);
  }

  void statement(const Stmt& s) {
    const size_t temps = temp_top_;
    if (s.kind != StmtKind::Label) line_entry(s.offset);
    switch (s.kind) {
      case StmtKind::Expr:
        expression_statement(s);
        break;
      case StmtKind::Assign:
        assignment(s);
        break;
      case StmtKind::IncDec:
        incdec(s);
        break;
      case StmtKind::If:
        if_statement(s);
        break;
      case StmtKind::While:
        while_statement(s);
        break;
      case StmtKind::For:
        for_statement(s);
        break;
      case StmtKind::Until: {
        // Suspends the program, not the drive: poll once per slice (2.12.3).
        const auto top = cb_.new_label(), done = cb_.new_label();
        cb_.bind(top);
        branch(*s.value, Op::JNZ, done);  // `until (MS == 0)` becomes one UNTILCK (peephole)
        emit(Op::YIELD);
        cb_.emit_to(Op::JMP, top);
        cb_.bind(done);
        eol(s);
        break;
      }
      case StmtKind::Wait:
        value(*s.value, Kind::Int);
        emit(Op::WAIT, kMicrosecondsPerMs);
        eol(s);
        break;
      case StmtKind::Switch:
        switch_statement(s);
        break;
      case StmtKind::Try:
        try_statement(s);
        break;
      case StmtKind::Break:
      case StmtKind::Continue: {
        for (auto it = loops_.rbegin(); it != loops_.rend(); ++it) {
          if (s.kind == StmtKind::Continue && !it->is_loop) continue;
          for (int k = it->try_depth; k < try_depth_; ++k) emit(Op::ENDTRY);
          cb_.emit_to(Op::JMP, s.kind == StmtKind::Break ? it->exit : it->next);
          break;
        }
        break;
      }
      case StmtKind::Return:
        emit(Op::RET);
        break;
      case StmtKind::Exit:
        emit(Op::EXIT);
        break;
      case StmtKind::Goto: {
        auto it = goto_labels_.find(label_key(s.name, s.auto_label));
        if (it != goto_labels_.end())
          cb_.emit_to(Op::JMP, it->second);
        else
          reset_to(s.name);  // goto #@AUTOEXEC of "function AUTOEXEC()"
        break;
      }
      case StmtKind::Reset:
        reset_to(s.name);
        break;
      case StmtKind::Label:
        bind_label_stmt(s);
        break;
    }
    temp_top_ = temps;
  }

  void reset_to(std::string_view name) {
    if (fixups) {
      fixups->push_back({here(), name});
      emit(Op::RESET, 0);
      return;
    }
    auto r = routine_of_label.find(std::string(name));
    emit(Op::RESET, r == routine_of_label.end() ? 0u : static_cast<uint32_t>(r->second));
  }

  void expression_statement(const Stmt& s) {
    const Expr& e = *s.value;
    if (e.kind == ExprKind::Ref && e.ref == RefKind::Function) {
      call(e, 0);
    } else if (e.kind == ExprKind::Ref && e.ref == RefKind::Command &&
               (e.command->flags & kAction)) {
      emit(Op::CMDRUN, e.command->id, 0);
    } else if (show) {
      show(e);
    } else {
      value(e);
      drop(operand_kind(e.type));
    }
    eol(s);
  }

  void assignment(const Stmt& s) {
    if (!s.bracketed || s.targets.size() == 1) {
      if (s.bracketed && s.value->kind == ExprKind::Ref && s.value->ref == RefKind::Function) {
        const StoreHow how = store_prefix(*s.targets[0]);
        call(*s.value, 1);
        convert(s.value->type, target_kind(*s.targets[0]));
        store(*s.targets[0], how);
      } else {
        assign(*s.targets[0], *s.value);
      }
      eol(s);
      return;
    }
    // [a, b] = f(x): the outputs land on the stack in order; keep them in temporaries so that
    // targets with indices can be stored one by one.
    const Expr& c = *s.value;
    const FunctionSym& f = syms_->functions[static_cast<size_t>(c.slot)];
    call(c, static_cast<uint32_t>(s.targets.size()));
    std::vector<uint32_t> slots(s.targets.size());
    for (size_t i = s.targets.size(); i-- > 0;) {
      slots[i] = temp(value_type(f.def->outputs[i].type));
      emit(Op::STL, slots[i]);
    }
    for (size_t i = 0; i < s.targets.size(); ++i) {
      const StoreHow how = store_prefix(*s.targets[i]);
      emit(Op::LDL, slots[i]);
      convert(kind_of(f.def->outputs[i].type), target_kind(*s.targets[i]));
      store(*s.targets[i], how);
    }
    eol(s);
  }

  void incdec(const Stmt& s) {
    const Expr& t = *s.targets[0];
    const Kind k = target_kind(t);
    if (t.ref == RefKind::Local && k == Kind::Int) {
      cb_.emit_imm(Op::INCL, static_cast<int32_t>(t.slot), static_cast<uint32_t>(s.delta));
      eol(s);
      return;
    }
    // The index is computed once.
    int32_t index_slot = -1;
    const bool indexed =
        (t.ref == RefKind::Global && !scalar_zero_index(t) && (t.has_index || t.has_parens)) ||
        (t.ref == RefKind::Command && t.has_index && t.args[0]->kind != ExprKind::IntLit);
    if (indexed) {
      value(*t.args[0], Kind::Int, false);
      index_slot = static_cast<int32_t>(temp(ValueType::Int));
      emit(Op::STL, static_cast<uint32_t>(index_slot));
      emit(Op::LDL, static_cast<uint32_t>(index_slot));
    }
    // load
    if (t.ref == RefKind::Local)
      emit(Op::LDL, static_cast<uint32_t>(t.slot));
    else if (t.ref == RefKind::Global)
      emit(indexed ? Op::LDGX : Op::LDG, static_cast<uint32_t>(t.slot));
    else if (indexed)
      emit(Op::CMDGETX, t.command->id);
    else
      emit(Op::CMDGET, t.command->id,
           t.has_index ? static_cast<uint32_t>(t.args[0]->int_value) : 0u);
    if (indexed) {
      // [value] -> [index, value]
      emit(Op::LDL, static_cast<uint32_t>(index_slot));
      emit(Op::SWAP);
    }
    if (k == Kind::Int) {
      push_int(s.delta);
      emit(Op::ADDI);
    } else {
      push_float(static_cast<float>(s.delta));
      emit(Op::ADDF);
    }
    if (t.ref == RefKind::Local)
      emit(Op::STL, static_cast<uint32_t>(t.slot));
    else if (t.ref == RefKind::Global)
      emit(indexed ? Op::STGX : Op::STG, static_cast<uint32_t>(t.slot));
    else if (indexed)
      emit(Op::CMDSETX, t.command->id);
    else
      emit(Op::CMDSET, t.command->id,
           t.has_index ? static_cast<uint32_t>(t.args[0]->int_value) : 0u);
    eol(s);
  }

  void end_line(const Stmt& s) {
    if (s.end_offset == 0) return;
    line_entry(s.end_offset);
  }

  void if_statement(const Stmt& s) {
    const auto done = cb_.new_label();
    bool first = true;
    for (const IfArm& arm : s.arms) {
      const auto next_arm = cb_.new_label();
      if (arm.cond) {
        if (!first) line_entry(arm.cond->offset);
        branch_false(*arm.cond, next_arm);
        emit(Op::EOL);
      }
      first = false;
      block(arm.body);
      cb_.emit_to(Op::JMP, done);
      cb_.bind(next_arm);
    }
    cb_.bind(done);
  }

  struct Loop {
    CodeBuilder::Label next, exit;
    int try_depth;
    bool is_loop;  // false for a switch (break only)
  };

  void while_statement(const Stmt& s) {
    const auto top = cb_.new_label(), done = cb_.new_label();
    cb_.bind(top);
    branch_false(*s.value, done);
    emit(Op::EOL);
    loops_.push_back({top, done, try_depth_, true});
    block(s.body);
    loops_.pop_back();
    end_line(s);
    emit(Op::EOL);  // an empty "while(1) end" still ends a line each turn
    cb_.emit_to(Op::JMP, top);
    cb_.bind(done);
  }

  // for k = a:step:b — bounds evaluated once (2.12.2); step 0 is a run-time error.
  void for_statement(const Stmt& s) {
    const Expr& var = *s.targets[0];
    const Kind k = target_kind(var);
    const ValueType vt = k == Kind::Int ? ValueType::Int : ValueType::Float;
    assign(var, *s.value);
    int step_sign = 1;  // +1, -1, or 0 when known only at run time
    int32_t step_slot = -1;
    if (s.step) {
      const Expr& st = *s.step;
      int32_t c = 0;
      bool constant = false;
      if (st.kind == ExprKind::IntLit) {
        c = st.int_value;
        constant = true;
      } else if (st.kind == ExprKind::Unary && st.op == Tok::Minus &&
                 st.lhs->kind == ExprKind::IntLit) {
        c = -st.lhs->int_value;
        constant = true;
      }
      step_sign = constant ? (c > 0 ? 1 : c < 0 ? -1 : 0) : 0;
      value(st, k);
      step_slot = static_cast<int32_t>(temp(vt));
      emit(Op::STL, static_cast<uint32_t>(step_slot));
      if (!constant || c == 0) {
        const auto ok = cb_.new_label();
        emit(Op::LDL, static_cast<uint32_t>(step_slot));
        if (k == Kind::Float) emit(Op::TRUTHF);
        cb_.emit_to(Op::JNZ, ok);
        emit(Op::RAISE, kZeroForStep);
        cb_.bind(ok);
      }
    }
    value(*s.end, k);
    const uint32_t end_slot = temp(vt);
    emit(Op::STL, end_slot);
    emit(Op::EOL);
    const auto top = cb_.new_label(), next = cb_.new_label(), done = cb_.new_label();
    cb_.bind(top);
    auto test = [&](bool up) {
      value(var);
      emit(Op::LDL, end_slot);
      emit(k == Kind::Int ? Op::CMPI : Op::CMPF, up ? bytecode::kRelLe : bytecode::kRelGe);
    };
    if (step_sign != 0) {
      test(step_sign > 0);
    } else {
      const auto down = cb_.new_label(), tested = cb_.new_label();
      emit(Op::LDL, static_cast<uint32_t>(step_slot));
      if (k == Kind::Int) {
        push_int(0);
        emit(Op::CMPI, bytecode::kRelGt);
      } else {
        push_float(0.0f);
        emit(Op::CMPF, bytecode::kRelGt);
      }
      cb_.emit_to(Op::JZ, down);
      test(true);
      cb_.emit_to(Op::JMP, tested);
      cb_.bind(down);
      test(false);
      cb_.bind(tested);
    }
    cb_.emit_to(Op::JZ, done);
    loops_.push_back({next, done, try_depth_, true});
    block(s.body);
    loops_.pop_back();
    cb_.bind(next);
    end_line(s);
    if (var.ref == RefKind::Local && k == Kind::Int && step_slot < 0) {
      cb_.emit_imm(Op::INCL, static_cast<int32_t>(var.slot), 1u);
    } else {
      const StoreHow how = store_prefix(var);
      value(var);
      if (step_slot >= 0)
        emit(Op::LDL, static_cast<uint32_t>(step_slot));
      else if (k == Kind::Int)
        push_int(1);
      else
        push_float(1.0f);  // the implied step of a float variable is 1.0, not int bits (2.12.2)
      emit(k == Kind::Int ? Op::ADDI : Op::ADDF);
      store(var, how);
    }
    emit(Op::EOL);
    cb_.emit_to(Op::JMP, top);
    cb_.bind(done);
  }

  // The first case equal to the subject runs; no fall-through (2.11.3).
  void switch_statement(const Stmt& s) {
    const Kind sk = operand_kind(s.value->type);
    value(*s.value);
    uint32_t value_slot = 0, tag_slot = 0;
    if (sk == Kind::Dynamic) {
      tag_slot = temp(ValueType::Int);
      value_slot = temp(ValueType::Int);
      emit(Op::STL, tag_slot);
      emit(Op::STL, value_slot);
    } else {
      value_slot = temp(sk == Kind::Int ? ValueType::Int : ValueType::Float);
      emit(Op::STL, value_slot);
    }
    emit(Op::EOL);
    const auto done = cb_.new_label();
    loops_.push_back({done, done, try_depth_, false});
    for (const SwitchCase& c : s.cases) {
      line_entry(c.offset);
      const auto next_case = cb_.new_label();
      if (c.value) {
        const Kind ck = operand_kind(c.value->type);
        const Kind k = (sk == Kind::Float || ck == Kind::Float)       ? Kind::Float
                       : (sk == Kind::Dynamic || ck == Kind::Dynamic) ? Kind::Dynamic
                                                                      : Kind::Int;
        emit(Op::LDL, value_slot);
        if (sk == Kind::Dynamic) emit(Op::LDL, tag_slot);
        convert(sk, k);
        value(*c.value, k);
        if (k == Kind::Dynamic)
          emit(Op::CMPD, 0);
        else if (k == Kind::Int)
          emit(Op::CMPI, bytecode::kRelEq);
        else
          float_equality(true);
        cb_.emit_to(Op::JZ, next_case);
        emit(Op::EOL);
      }
      block(c.body);
      cb_.emit_to(Op::JMP, done);
      cb_.bind(next_case);
    }
    loops_.pop_back();
    cb_.bind(done);
  }

  void try_statement(const Stmt& s) {
    const auto handler = cb_.new_label(), done = cb_.new_label();
    cb_.emit_to(Op::TRY, handler);
    emit(Op::EOL);
    ++try_depth_;
    block(s.body);
    --try_depth_;
    emit(Op::ENDTRY);
    cb_.emit_to(Op::JMP, done);
    cb_.bind(handler);
    block(s.handler);
    cb_.bind(done);
  }

  size_t max_locals() const { return locals_->size(); }

 private:
  static std::string label_key(std::string_view name, bool is_auto) {
    return (is_auto ? "@" : "#") + std::string(name);
  }

  uint32_t constant(ValueType type, uint32_t bits) {
    const uint64_t key = (static_cast<uint64_t>(type) << 32) | bits;
    auto it = constants_.index.find(key);
    if (it != constants_.index.end()) return it->second;
    const uint32_t index = static_cast<uint32_t>(constants_.constants.size());
    constants_.constants.push_back({type, bits});
    constants_.index[key] = index;
    return index;
  }

  bytecode::Image& img_;
  CodeBuilder cb_;
  const Symbols* syms_;
  const Locator& loc_;
  std::vector<bytecode::Local>* locals_ = nullptr;
  size_t temp_base_ = 0, temp_top_ = 0;
  std::unordered_map<std::string, CodeBuilder::Label> goto_labels_;
  std::vector<Loop> loops_;
  int try_depth_ = 0;
  ConstantTable& constants_;
};

}  // namespace

void generate_function(const Symbols& symbols, int symbol, const Block& body, uint32_t end_offset,
                       const Locator& locator, ConstantTable& constants, bool with_lines,
                       FunctionCode& out) {
  bytecode::Image img;
  img.code = std::move(out.code);
  img.lines = std::move(out.lines);
  img.code.clear();
  img.lines.clear();
  out.fixups.clear();
  out.locals.clear();
  Gen gen(img, &symbols, locator, constants);
  gen.with_lines = with_lines;
  gen.globals_ = &symbols.globals;
  gen.fixups = &out.fixups;
  for (const LocalSym& l : symbols.functions[static_cast<size_t>(symbol)].locals)
    out.locals.push_back({l.name, value_type(l.type)});
  gen.begin_routine(&out.locals);
  gen.declare_goto_labels(body);
  gen.block(body);
  gen.line_entry(end_offset);
  gen.emit(Op::RET);
  out.ok = gen.finish();
  out.code = std::move(img.code);
  out.lines = std::move(img.lines);
}

namespace {

// The constants in order of first use in `code`, as one generator emitting the whole program in
// order would have numbered them.
void renumber_constants(bytecode::Image& img, const ConstantTable& table) {
  std::vector<uint32_t> renamed(table.constants.size(), UINT32_MAX);
  for (size_t pc = 0; pc < img.code.size();
       pc += bytecode::op_length(bytecode::word_op(img.code[pc]))) {
    const Op op = bytecode::word_op(img.code[pc]);
    if (bytecode::op_info(op).a != bytecode::Operand::Const) continue;
    uint32_t& k = renamed[bytecode::word_a(img.code[pc])];
    if (k == UINT32_MAX) {
      k = static_cast<uint32_t>(img.constants.size());
      img.constants.push_back(table.constants[bytecode::word_a(img.code[pc])]);
    }
    img.code[pc] = bytecode::make_word(op, k);
  }
}

// Adds `e` after the entries already in `lines` by line_entry()'s rule.
void append_line(std::vector<bytecode::LineEntry>& lines, const bytecode::LineEntry& e) {
  if (!lines.empty() && lines.back().line == e.line && lines.back().file == e.file) return;
  if (!lines.empty() && lines.back().code == e.code) {
    lines.back().line = e.line;
    lines.back().file = e.file;
    return;
  }
  lines.push_back(e);
}

}  // namespace

bytecode::Image generate_program(const Program& program, const Symbols& symbols,
                                 const std::vector<const FunctionCode*>& bodies,
                                 uint32_t body_words, bool bodies_ok, const Locator& locator,
                                 Reporter& reporter, ConstantTable& constants, bool check_only) {
  bytecode::Image img;
  if (check_only) {
    // Only the code's soundness and size count: no routines, no line table, no image.
    Gen gen(img, &symbols, locator, constants);
    gen.with_lines = false;
    gen.globals_ = &symbols.globals;
    std::vector<RoutineFixup> ignored;
    gen.fixups = &ignored;
    std::vector<bytecode::Local> top_locals;
    gen.begin_routine(&top_locals);
    gen.declare_goto_labels(program.top);
    for (const StmtPtr& s : program.top) gen.statement(*s);
    if (!gen.finish() || !bodies_ok) reporter.error(Error::InternalCompilerError, 0);
    if (img.code.size() + body_words > bytecode::kOperandMax)
      reporter.error(Error::CompiledCodeTooLong, 0);
    return {};
  }
  for (const GlobalSym& g : symbols.globals)
    img.globals.push_back(
        {g.name, value_type(g.type), g.length == 0 ? 1u : static_cast<uint32_t>(g.length)});
  Gen gen(img, &symbols, locator, constants);
  gen.globals_ = &symbols.globals;

  // Routine numbers: functions with a body first, then the top-level labels in order.
  gen.routine_of_function.assign(symbols.functions.size(), -1);
  for (size_t i = 0; i < symbols.functions.size(); ++i) {
    const FunctionSym& f = symbols.functions[i];
    if (!f.has_body) continue;
    gen.routine_of_function[i] = static_cast<int32_t>(img.routines.size());
    gen.routine_of_label[f.name] = static_cast<int32_t>(img.routines.size());
    bytecode::Routine r;
    r.name = f.name;
    r.kind = f.is_auto ? bytecode::RoutineKind::AutoRoutine : bytecode::RoutineKind::Function;
    r.inputs = static_cast<uint32_t>(f.inputs);
    r.outputs = static_cast<uint32_t>(f.outputs);
    img.routines.push_back(std::move(r));
  }
  std::vector<size_t> label_routines;
  for (const StmtPtr& s : program.top) {
    if (s->kind != StmtKind::Label) continue;
    const std::string name(s->name);
    if (gen.routine_of_label.count(name)) continue;
    gen.routine_of_label[name] = static_cast<int32_t>(img.routines.size());
    label_routines.push_back(img.routines.size());
    bytecode::Routine r;
    r.name = name;
    r.kind = s->auto_label ? bytecode::RoutineKind::AutoRoutine : bytecode::RoutineKind::Label;
    img.routines.push_back(std::move(r));
  }

  // The top level: one stream of code in which each label is an entry; its routines share one
  // set of temporaries because control may fall from one label into the next.
  std::vector<bytecode::Local> top_locals;
  gen.begin_routine(&top_locals);
  gen.declare_goto_labels(program.top);
  for (const StmtPtr& s : program.top) {
    if (s->kind == StmtKind::Label) {
      auto it = gen.routine_of_label.find(std::string(s->name));
      if (it != gen.routine_of_label.end() &&
          img.routines[static_cast<size_t>(it->second)].entry == 0 &&
          img.routines[static_cast<size_t>(it->second)].kind != bytecode::RoutineKind::Function)
        img.routines[static_cast<size_t>(it->second)].entry = gen.here();
    }
    gen.statement(*s);
  }
  for (size_t r : label_routines) img.routines[r].locals = top_locals;
  bool ok = gen.finish() && bodies_ok;

  // The functions, generated one by one as they were checked, follow in order.
  for (size_t i = 0; i < symbols.functions.size(); ++i) {
    if (!symbols.functions[i].has_body) continue;
    const FunctionCode* body = bodies[i];
    if (body == nullptr) continue;  // not kept: counted in body_words
    ok = ok && body->ok;
    bytecode::Routine& r = img.routines[static_cast<size_t>(gen.routine_of_function[i])];
    const uint32_t base = static_cast<uint32_t>(img.code.size());
    r.entry = base;
    r.locals = body->locals;
    for (size_t pc = 0; pc < body->code.size();) {
      uint32_t word = body->code[pc];
      const Op op = bytecode::word_op(word);
      if (bytecode::op_info(op).a == bytecode::Operand::Target)
        word = bytecode::make_word(op, bytecode::word_a(word) + base);
      img.code.push_back(word);
      for (uint32_t k = 1; k < bytecode::op_length(op); ++k) img.code.push_back(body->code[pc + k]);
      pc += bytecode::op_length(op);
    }
    for (const RoutineFixup& f : body->fixups) {
      auto it = gen.routine_of_label.find(std::string(f.name));
      const uint32_t routine = it == gen.routine_of_label.end() || it->second < 0
                                   ? 0u
                                   : static_cast<uint32_t>(it->second);
      uint32_t& word = img.code[base + f.pc];
      word = bytecode::make_word(bytecode::word_op(word), routine);
    }
    for (const bytecode::LineEntry& e : body->lines)
      append_line(img.lines, {e.code + base, e.file, e.line});
  }

  // Auto-routines answer their events.
  for (size_t i = 0; i < img.routines.size(); ++i) {
    if (img.routines[i].kind != bytecode::RoutineKind::AutoRoutine) continue;
    if (const AutoRoutineName* a = find_auto_routine(img.routines[i].name))
      img.events.push_back({a->event, static_cast<uint32_t>(i)});
  }
  // A program of declarations only still loads: its globals serve the command line.
  if (img.code.empty() && body_words == 0) gen.emit(Op::RET);
  if (!ok) reporter.error(Error::InternalCompilerError, 0);
  if (img.code.size() + body_words > bytecode::kOperandMax)
    reporter.error(Error::CompiledCodeTooLong, 0);
  renumber_constants(img, constants);
  img.dialect = "gold";
  img.info.push_back("dialect=gold");
  return img;
}

bytecode::Image generate_line(const Block& block, const std::vector<KnownGlobal>& known,
                              const Locator& locator, Reporter& reporter,
                              std::vector<LineValue>& values) {
  bytecode::Image img;
  std::vector<GlobalSym> globals;
  for (const KnownGlobal& g : known) {
    img.globals.push_back(
        {g.name, value_type(g.type), g.length == 0 ? 1u : static_cast<uint32_t>(g.length)});
    globals.push_back({g.name, g.type, g.length, 0});
  }
  ConstantTable constants;
  Gen gen(img, nullptr, locator, constants);
  gen.globals_ = &globals;
  bytecode::Routine r;
  r.name = "$line";
  r.kind = bytecode::RoutineKind::Function;
  gen.begin_routine(&r.locals);
  gen.show = [&](const Expr& e) {
    // A bare value is kept in a fresh global with its kind, for the command line to print.
    const Kind k = operand_kind(e.type);
    LineValue v;
    v.kind = k;
    v.value_global = static_cast<uint32_t>(img.globals.size());
    img.globals.push_back({"$value" + std::to_string(values.size()),
                           k == Kind::Float ? ValueType::Float : ValueType::Int, 1});
    if (k == Kind::Dynamic) {
      v.tag_global = static_cast<int32_t>(img.globals.size());
      img.globals.push_back({"$tag" + std::to_string(values.size()), ValueType::Int, 1});
    }
    gen.value(e);
    if (k == Kind::Dynamic) gen.emit(Op::STG, static_cast<uint32_t>(v.tag_global));
    gen.emit(Op::STG, v.value_global);
    values.push_back(v);
  };
  gen.block(block);
  gen.emit(Op::RET);
  img.routines.push_back(std::move(r));
  if (!gen.finish()) reporter.error(Error::InternalCompilerError, 0);
  img.constants = std::move(constants.constants);
  img.dialect = "gold";
  img.info.push_back("dialect=gold");
  return img;
}

}  // namespace uprog::gold
