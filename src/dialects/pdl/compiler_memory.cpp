// The compiler's places and memory (1.3, 2.1): user variables in the 400 words, locals in the
// task's stack frame, pointers checked to be the program's addresses of words (0..399,
// 0x1000*t + k, bit 29 for a float), which are the data memory's own, system variables and
// states through the host;
// and the assignments, including the ones that fill blocks of words (initialisers, strings,
// memcpy, memset) and the reductions (memmin, memmax, memsum).
#include "dialects/pdl/compiler.h"
#include "vm/run_error.h"

namespace uprog::pdl {
namespace {

bool is_memory_function(std::string_view name) {
  return equal_ignoring_case(name, "memcpy") || equal_ignoring_case(name, "memset");
}

bool is_reduction(std::string_view name) {
  return equal_ignoring_case(name, "memmin") || equal_ignoring_case(name, "memmax") ||
         equal_ignoring_case(name, "memsum");
}

constexpr uint32_t kCmpLess = 2;

}  // namespace

const Var* Compiler::find_var(const std::string& name) const {
  for (const Var& v : locals_)
    if (v.name == name) return &v;
  for (const Var& v : globals_)
    if (v.name == name) return &v;
  return nullptr;
}

bool Compiler::has_prefix(const Place& p) const {
  return p.form == Place::Form::Memory || p.form == Place::Form::SystemX ||
         p.form == Place::Form::StateX;
}

// A variable's value (its element 0).
void Compiler::read_var(const Var& v) {
  if (!v.local) {
    code_.emit(Op::LDG, static_cast<uint32_t>(v.global));
    return;
  }
  emit_frame_address(v.address);
  code_.emit(Op::LDM);
}

// The address of the current procedure's frame word `index` (a word of its parameters and
// variables): the frame pointer plus the index, which the VM's frame-word instructions fuse.
void Compiler::emit_frame_address(int32_t index) { emit_stack_address(kFp, index); }

// A stack register (sp, fp) plus an offset: the address of a word of the task's stack.
void Compiler::emit_stack_address(uint32_t reg, int32_t offset) {
  code_.emit(Op::LDL, reg);
  push_int(offset);
  code_.emit(Op::ADDI);
}

void Compiler::emit_increment(const Var& v, int32_t by) {
  if (!v.local) {
    code_.emit(Op::LDG, static_cast<uint32_t>(v.global));
    push_int(by);
    code_.emit(Op::ADDI);
    if (v.kind == Kind::Short && !v.pointer) code_.emit(Op::SEXT, 16);
    code_.emit(Op::STG, static_cast<uint32_t>(v.global));
    return;
  }
  emit_frame_address(v.address);
  code_.emit(Op::DUP);
  code_.emit(Op::LDM);
  push_int(by);
  code_.emit(Op::ADDI);
  code_.emit(Op::STM);
}

void Compiler::emit_post_increments(const Place& p) {
  for (const Var* v : p.post_increments) emit_increment(*v, 1);
}

// An index on the stack made the address of its word in array v: the index first, so that the
// VM fuses a global index with the array's address (ADDGK), and nothing added for the array at
// the user memory's word 0.
void Compiler::add_base_address(const Var& v) {
  if (v.local) {
    emit_frame_address(v.address);
    code_.emit(Op::ADDI);
  } else if (v.address != 0) {
    push_int(v.address);
    code_.emit(Op::ADDI);
  }
}

// A flat address in the user memory, else BadAddress.
void Compiler::emit_user_check() {
  CodeBuilder::Label ok = code_.new_label();
  code_.emit(Op::DUP);
  push_int(kUserWords);
  code_.emit(Op::CMPU, kCmpLess);
  code_.emit_to(Op::JNZ, ok);
  code_.emit(Op::RAISE, static_cast<uint32_t>(vm::RunError::BadAddress));
  code_.bind(ok);
}

// A program's address (bit 29 ignored) checked: 0..399, or 0x1000*t + k (t = 1..3, k < 256), are
// the data memory's words themselves (layout.h); anything else is BadAddress. The two common
// cases first, each one unsigned comparison: the user memory, then the task's own stack (a
// pointer to a caller's local). A float's address (float_address) has its bit 29 cleared first;
// any other comes through the general check.
void Compiler::emit_pointer_check(bool float_address) {
  if (float_address) {
    push_int(~kFloatAddressBit);
    code_.emit(Op::ANDI);
  }
  emit_word_check(true);
}

// An address of a word that a program may reach, else BadAddress; with ignore_float_bit, bit 29
// set where the type did not say so is cleared.
void Compiler::emit_word_check(bool ignore_float_bit) {
  CodeBuilder::Label done = code_.new_label();
  code_.emit(Op::DUP);
  push_int(kUserWords);
  code_.emit(Op::CMPU, kCmpLess);
  code_.emit_to(Op::JNZ, done);
  code_.emit(Op::DUP);
  code_.emit(Op::LDL, kBase);
  code_.emit(Op::SUBI);
  push_int(kStackWords);
  code_.emit(Op::CMPU, kCmpLess);
  code_.emit_to(Op::JNZ, done);
  if (ignore_float_bit) {
    push_int(~kFloatAddressBit);
    code_.emit(Op::ANDI);
  }
  CodeBuilder::Label stack = code_.new_label(), bad = code_.new_label();
  code_.emit(Op::DUP);
  push_int(kTaskAddressUnit);
  code_.emit_to(Op::JGEI, stack);
  code_.emit(Op::DUP);  // below 0x1000 (or negative): the user memory's words only
  push_int(kUserWords);
  code_.emit(Op::CMPU, kCmpLess);
  code_.emit_to(Op::JNZ, done);
  code_.bind(bad);
  code_.emit(Op::RAISE, static_cast<uint32_t>(vm::RunError::BadAddress));
  code_.bind(stack);
  // 0x1000..0x3FFF with bits 8..11 clear: task a >> 12 (1..3), word a & 0xFF.
  constexpr int32_t kNotStackBits = ~(kTaskAddressUnit * 4 - 1) | (kTaskAddressUnit - kStackWords);
  static_assert(kTasks == 3 && kStackWords == 256 && stack_base(1) == kTaskAddressUnit,
                "t in bits 12..13, k in bits 0..7");
  code_.emit(Op::DUP);
  push_int(kNotStackBits);
  code_.emit(Op::ANDI);
  code_.emit_to(Op::JNZ, bad);
  code_.bind(done);
}

// `&v`, `&v[i]`, `*p`, `*p[i]` and a bare array name: the program's address of the first word.
bool Compiler::logical_address(bool) {
  address_short_ = false;
  if (accept_op("*")) {
    const Token& t = peek();
    const std::string name = expect_name();
    const Var* v = find_var(name);
    if (!v || !v->pointer) {
      error(v ? Error::NotAPointer : Error::UnknownName, t.offset, name);
      return false;
    }
    read_var(*v);
    if (accept_op("[")) {
      int_operand(expr(), t.offset);
      expect_op("]");
      code_.emit(Op::ADDI);
    }
    address_float_ = v->kind == Kind::Float;
    return true;
  }
  const Token& t = peek();
  if (t.kind != Tok::Name) {
    error(Error::Expected, t.offset, "a variable");
    return false;
  }
  next();
  const Var* v = find_var(t.text);
  if (!v) {
    const bool system = find_system_variable(t.text) || find_state(t.text);
    error(system ? Error::AddressOfSystem : Error::UnknownName, t.offset, t.text);
    if (accept_op("[")) {
      expr();
      code_.emit(Op::POP);
      expect_op("]");
    }
    return false;
  }
  address_float_ = v->kind == Kind::Float && !v->pointer;
  address_short_ = v->kind == Kind::Short && !v->pointer;
  // A global's own address is a constant, its float bit included (`lerp(x, &tot);`: one push).
  if (!v->local && !at_op("[")) {
    push_int(v->address | (address_float_ ? kFloatAddressBit : 0));
    return true;
  }
  if (v->local) {
    emit_frame_address(v->address);
  } else {
    push_int(v->address);
  }
  if (accept_op("[")) {
    int_operand(expr(), t.offset);
    expect_op("]");
    code_.emit(Op::ADDI);
  }
  if (address_float_) {
    push_int(kFloatAddressBit);
    code_.emit(Op::ORI);
  }
  return true;
}

std::optional<Place> Compiler::parse_place(bool for_store) {
  const Token& t = peek();
  Place p;
  if (at_op("*")) {
    if (!logical_address(for_store)) return std::nullopt;
    emit_pointer_check(address_float_);
    p.form = Place::Form::Memory;
    p.type = address_float_ ? Ty::Float : Ty::Int;
    return p;
  }
  if (at_op("<")) {
    next();
    int_operand(primary(false), t.offset);
    expect_op(">");
    p.form = Place::Form::StateX;
    return p;
  }
  if (t.kind != Tok::Name) {
    error(Error::Expected, t.offset, "a variable before '" + t.text + "'");
    return std::nullopt;
  }
  next();
  if (const Var* v = find_var(t.text)) {
    p.var = v;
    p.type = v->type();
    p.is_short = v->kind == Kind::Short && !v->pointer;
    bool constant = true;
    int32_t index = 0;
    if (accept_op("[")) {
      if (peek().kind == Tok::Int && at_op("]", 1)) {
        index = next().int_value;
      } else if (peek().kind == Tok::Name && at_op("+", 1) && at_op("]", 2)) {
        // [n+]: index auto increase (2.1.1), after the access.
        const Token& n = next();
        next();
        const Var* nv = find_var(n.text);
        if (!nv) {
          error(Error::UnknownName, n.offset, n.text);
          return std::nullopt;
        }
        constant = false;
        p.post_increments.push_back(nv);
        if (nv->kind == Kind::Float && !nv->pointer) error(Error::IntegerNeeded, n.offset, n.text);
        read_var(*nv);
        add_base_address(*v);
      } else {
        constant = false;
        int_operand(expr(), t.offset);
        add_base_address(*v);
      }
      expect_op("]");
    }
    p.form = Place::Form::Memory;
    if (!constant) {
      // An index past a local array may reach any word a pointer may, and no other.
      if (v->local)
        emit_word_check(false);
      else
        emit_user_check();
      return p;
    }
    if (v->local) {
      if (index >= 0 && index < static_cast<int32_t>(v->length)) {
        p.form = Place::Form::Frame;
        p.index = v->address + index;
        return p;
      }
      emit_frame_address(v->address + index);
      emit_word_check(false);  // an index outside the array
      return p;
    }
    const int32_t flat = v->address + index;
    for (const Var& g : globals_) {
      if (g.address == flat) {
        p.form = Place::Form::Global;
        p.global = g.global;
        return p;
      }
    }
    push_int(flat);
    if (flat < 0 || flat >= kUserWords) emit_user_check();
    return p;
  }
  if (const StateName* s = find_state(t.text)) {
    p.form = Place::Form::State;
    p.index = s->number;
    return p;
  }
  bool axis_zero = false;
  if (const SystemVariable* s = find_system_variable(t.text, &axis_zero)) {
    if (for_store && !s->writable()) error(Error::ReadOnly, t.offset, t.text);
    if (!for_store && !s->readable()) error(Error::WriteOnly, t.offset, t.text);
    p.system = s;
    p.slave = s->slave;
    p.command = s->id;
    p.form = Place::Form::System;
    if (accept_op("[")) {  // X_acc[0] is acc[0]: any variable may be indexed (1.3)
      if (peek().kind == Tok::Int && at_op("]", 1)) {
        p.index = next().int_value;
      } else {
        int_operand(expr(), t.offset);
        p.form = Place::Form::SystemX;
      }
      expect_op("]");
    }
    return p;
  }
  error(Error::UnknownName, t.offset, t.text);
  if (accept_op("[")) {
    while (!at_op("]") && peek().kind != Tok::End && !peek().line_start) next();
    accept_op("]");
  }
  return std::nullopt;
}

void Compiler::emit_load(const Place& p, bool keep_prefix) {
  if (keep_prefix && has_prefix(p)) code_.emit(Op::DUP);
  switch (p.form) {
    case Place::Form::Global:
      code_.emit(Op::LDG, static_cast<uint32_t>(p.global));
      break;
    case Place::Form::Memory:
      code_.emit(Op::LDM);
      break;
    case Place::Form::Frame:
      emit_frame_address(p.index);
      code_.emit(Op::LDM);
      break;
    case Place::Form::System:
      code_.emit(Op::CMDGET, p.command, static_cast<uint32_t>(p.index));
      break;
    case Place::Form::SystemX:
      code_.emit(Op::CMDGETX, p.command);
      break;
    case Place::Form::State:
      code_.emit(Op::CMDGET, kStateCommand, static_cast<uint32_t>(p.index));
      break;
    case Place::Form::StateX:
      code_.emit(Op::CMDGETX, kStateCommand);
      break;
  }
  if (!keep_prefix) {
    if (p.slave) ++slave_reads_;
    emit_post_increments(p);
  }
}

void Compiler::emit_store(const Place& p) {
  switch (p.form) {
    case Place::Form::Global:
      code_.emit(Op::STG, static_cast<uint32_t>(p.global));
      break;
    case Place::Form::Memory:
      code_.emit(Op::STM);
      break;
    case Place::Form::Frame:
      // The value first, then its word's address: the VM makes the five one store (STMLK).
      emit_frame_address(p.index);
      code_.emit(Op::SWAP);
      code_.emit(Op::STM);
      break;
    case Place::Form::System:
      code_.emit(Op::CMDSET, p.command, static_cast<uint32_t>(p.index));
      break;
    case Place::Form::SystemX:
      code_.emit(Op::CMDSETX, p.command);
      break;
    case Place::Form::State:
      code_.emit(Op::CMDSET, kStateCommand, static_cast<uint32_t>(p.index));
      break;
    case Place::Form::StateX:
      code_.emit(Op::CMDSETX, kStateCommand);
      break;
  }
}

void Compiler::assignment() {
  const size_t at = peek().offset;
  // The assignment's operator, at bracket depth 0 on this command's line.
  size_t op_at = 0;
  int depth = 0;
  for (size_t k = 0; k < 256; ++k) {
    const Token& a = peek(k);
    if (a.kind == Tok::End || (k > 0 && a.line_start) || (a.kind == Tok::Op && a.text == ";"))
      break;
    if (a.kind != Tok::Op) continue;
    if (a.text == "(" || a.text == "[") ++depth;
    if (a.text == ")" || a.text == "]") --depth;
    if (depth == 0 &&
        (a.text == "=" || a.text == "++" || a.text == "--" ||
         (a.text.size() == 2 && a.text[1] == '=' && a.text[0] != '<' && a.text[0] != '>'))) {
      op_at = k;
      break;
    }
  }
  if (op_at == 0) {
    error(Error::Syntax, at, "not a command: '" + peek().text + "'");
    return;
  }
  const Token& after = peek(op_at + 1);
  if (peek(op_at).text == "=" &&
      ((after.kind == Tok::Op && after.text == "{") || after.kind == Tok::String ||
       (after.kind == Tok::Name && is_memory_function(after.text) && !find_var(after.text)))) {
    if (after.kind == Tok::Name) {
      call_first_ = pos_ + op_at + 1;
      call_end_ = command_end(call_first_);
      if (!check_call_alone(call_first_)) return;
    }
    return memory_block_assignment(at);
  }
  begin_command(1);
  std::optional<Place> p = parse_place(true);
  if (!p) return;
  slave_reads_ = 0;
  operations_ = 0;
  const Token& op = next();
  if (op.text == "++" || op.text == "--") {
    if (is_float(p->type) || p->form == Place::Form::State || p->form == Place::Form::StateX) {
      error(Error::IntegerNeeded, op.offset, "++ and -- of long and short variables");
    }
    emit_load(*p, true);  // a Memory place's address stays below
    push_int(1);
    code_.emit(op.text == "++" ? Op::ADDI : Op::SUBI);
    convert(Ty::Int, p->type, p->is_short);
    emit_store(*p);
    emit_post_increments(*p);
    end_line();
    return;
  }
  const bool is_state = p->form == Place::Form::State || p->form == Place::Form::StateX;
  if (op.text == "=") {
    if (is_state) {
      if (in_short_if_) error(Error::ShortIfCommand, at, "state assignment");
      condition();
      emit_store(*p);
      emit_post_increments(*p);
      end_line();
      return;
    }
    const Token& rhs = peek();
    call_first_ = pos_;
    call_end_ = command_end(pos_);
    if (rhs.kind == Tok::Name && is_reduction(rhs.text) && at_op("(", 1) && !find_var(rhs.text)) {
      if (!check_call_alone(pos_)) return;
      next();
      CodeBuilder::Label skip = code_.new_label(), done = code_.new_label();
      const Ty t = memory_reduction(rhs.text, rhs.offset, skip, has_prefix(*p));
      convert(t, p->type, p->is_short);
      emit_store(*p);
      code_.emit_to(Op::JMP, done);
      code_.bind(skip);
      if (has_prefix(*p)) code_.emit(Op::POP);
      code_.bind(done);
      emit_post_increments(*p);
      end_line();
      return;
    }
    check_assignment_form(call_first_, call_end_, false);
    integer_quotient_ = strict_forms_ && !is_float(p->type);
    const Ty t = expr();
    integer_quotient_ = false;
    call_first_ = SIZE_MAX;
    if (p->slave && slave_reads_ > 0 && operations_ == 0) error(Error::SlaveBothSides, at);
    if (slave_reads_ > 0 && operations_ > 0) error(Error::SlaveOnRight, at);
    convert(t, p->type, p->is_short);
    emit_store(*p);
    emit_post_increments(*p);
    end_line();
    return;
  }
  if (is_state) error(Error::NotAssignable, op.offset, "an operation assignment to a state");
  emit_load(*p, true);  // a Memory place's address stays below
  check_assignment_form(pos_, command_end(pos_), true);
  const Ty t = expr();
  if (slave_reads_ > 0) error(Error::SlaveOnRight, at);
  integer_quotient_ = strict_forms_ && !is_float(p->type);
  const Ty r = arith(std::string_view(op.text).substr(0, 1), p->type, t, op.offset);
  integer_quotient_ = false;
  convert(r, p->type, p->is_short);
  emit_store(*p);
  emit_post_increments(*p);
  end_line();
}

// `v = {…}`, `v = "…"`, `v = memcpy(src, n)`, `v = memset(value, n)`: words from v's address on.
void Compiler::memory_block_assignment(size_t lhs_start) {
  begin_command(1);
  if (!logical_address(true)) return;
  const bool dest_float = address_float_, dest_short = address_short_;
  const uint32_t d = scratch();
  code_.emit(Op::STL, d);
  expect_op("=");
  auto store_word = [&](int32_t i) {
    code_.emit(Op::LDL, d);
    push_int(i);
    code_.emit(Op::ADDI);
    emit_pointer_check(dest_float);
  };
  if (accept_op("{")) {
    int32_t k = 0;
    while (!at_op("}") && peek().kind != Tok::End) {
      const size_t value_at = peek().offset;
      store_word(k);
      const Ty t = expr();
      convert(t, dest_float ? Ty::Float : Ty::Int, dest_short);
      code_.emit(Op::STM);
      if (++k == 8) error(Error::TooManyInitValues, value_at);
      if (!accept_op(",")) break;
    }
    expect_op("}");
    slots_ += static_cast<uint32_t>(k);
  } else if (peek().kind == Tok::String) {
    // 4 characters a word, low byte first, NUL-ended (pdl-drive.md).
    const std::string text = next().text;
    const size_t words = text.size() / 4 + 1;
    for (size_t w = 0; w < words; ++w) {
      uint32_t word = 0;
      for (size_t b = 0; b < 4; ++b) {
        const size_t i = w * 4 + b;
        if (i < text.size())
          word |= static_cast<uint32_t>(static_cast<unsigned char>(text[i])) << (8 * b);
      }
      store_word(static_cast<int32_t>(w));
      push_int(static_cast<int32_t>(word));
      code_.emit(Op::STM);
    }
    slots_ += static_cast<uint32_t>(words);
  } else {
    const Token& f = next();
    const bool set = equal_ignoring_case(f.text, "memset");
    expect_op("(");
    const uint32_t s = scratch(), n = scratch();
    if (set) {
      const size_t value_at = peek().offset;
      const size_t first = pos_;
      const Ty t = expr();
      check_function_argument(first, pos_, false);
      const bool constant = is_literal(first, pos_);
      if (is_float(t) != dest_float && !constant)
        error(Error::ArgumentType, value_at, "memset does not convert");
      convert(t, dest_float ? Ty::Float : Ty::Int, dest_short);
    } else {
      const size_t src_at = peek().offset;
      if (!logical_address(false)) {
        push_int(0);
      } else if (address_float_ != dest_float) {
        error(Error::ArgumentType, src_at, "memcpy copies between arrays of one type");
      }
    }
    code_.emit(Op::STL, s);
    expect_op(",");
    const size_t count_first = pos_;
    int_operand(expr(), f.offset);
    check_function_argument(count_first, pos_, true);
    code_.emit(Op::STL, n);
    expect_op(")");
    emit_copy_loop(set, dest_float, d, s, n);
    emit_phase_yields(n, set ? 40 : 20);
    release(2);
  }
  release(1);
  (void)lhs_start;
  end_line();
}

void Compiler::emit_copy_loop(bool set, bool is_float, uint32_t d, uint32_t s, uint32_t n) {
  const uint32_t i = scratch();
  push_int(0);
  code_.emit(Op::STL, i);
  CodeBuilder::Label top = code_.new_label(), done = code_.new_label();
  code_.bind(top);
  code_.emit(Op::LDL, i);
  code_.emit(Op::LDL, n);
  code_.emit_to(Op::JGEI, done);
  code_.emit(Op::LDL, d);
  code_.emit(Op::LDL, i);
  code_.emit(Op::ADDI);
  emit_pointer_check(is_float);
  code_.emit(Op::LDL, s);
  if (!set) {
    code_.emit(Op::LDL, i);
    code_.emit(Op::ADDI);
    emit_pointer_check(is_float);
    code_.emit(Op::LDM);
  }
  code_.emit(Op::STM);
  code_.emit(Op::INCL, i, 1);
  code_.emit_to(Op::JMP, top);
  code_.bind(done);
  release(1);
}

// The phases a block command takes beyond its first: n / per_phase turns (2.3.9 - 2.3.12).
void Compiler::emit_phase_yields(uint32_t n_local, int32_t per_phase) {
  const uint32_t k = scratch();
  code_.emit(Op::LDL, n_local);
  push_int(per_phase);
  code_.emit(Op::DIVI);
  code_.emit(Op::STL, k);
  CodeBuilder::Label top = code_.new_label(), done = code_.new_label();
  code_.bind(top);
  code_.emit(Op::LDL, k);
  push_int(0);
  code_.emit_to(Op::JLEI, done);
  code_.emit(Op::INCL, k, static_cast<uint32_t>(-1));
  code_.emit(Op::YIELD);
  code_.emit_to(Op::JMP, top);
  code_.bind(done);
  release(1);
}

// memmin/memmax/memsum(src, n): the value on the stack; with n <= 0 a jump to `skip`, where
// the destination stays as it was (2.3.11).
Ty Compiler::memory_reduction(const std::string& raw, size_t at, CodeBuilder::Label skip, bool) {
  const bool sum = equal_ignoring_case(raw, "memsum"), max = equal_ignoring_case(raw, "memmax");
  expect_op("(");
  const uint32_t s = scratch(), n = scratch(), acc = scratch(), i = scratch();
  bool f = false;
  if (logical_address(false)) {
    f = address_float_;
  } else {
    push_int(0);
  }
  code_.emit(Op::STL, s);
  expect_op(",");
  const size_t count_first = pos_;
  int_operand(expr(), at);
  check_function_argument(count_first, pos_, true);
  code_.emit(Op::STL, n);
  expect_op(")");
  code_.emit(Op::LDL, n);
  push_int(0);
  code_.emit_to(Op::JLEI, skip);
  code_.emit(Op::LDL, s);
  emit_pointer_check(f);
  code_.emit(Op::LDM);
  code_.emit(Op::STL, acc);
  push_int(1);
  code_.emit(Op::STL, i);
  CodeBuilder::Label top = code_.new_label(), done = code_.new_label();
  code_.bind(top);
  code_.emit(Op::LDL, i);
  code_.emit(Op::LDL, n);
  code_.emit_to(Op::JGEI, done);
  code_.emit(Op::LDL, acc);
  code_.emit(Op::LDL, s);
  code_.emit(Op::LDL, i);
  code_.emit(Op::ADDI);
  emit_pointer_check(f);
  code_.emit(Op::LDM);
  if (sum) {
    code_.emit(f ? Op::ADDF : Op::ADDI);
    code_.emit(Op::STL, acc);
  } else {
    // Keep the element when it beats acc: [acc, e] -> acc.
    const uint32_t e = scratch();
    code_.emit(Op::STL, e);
    code_.emit(Op::LDL, e);
    code_.emit(f ? Op::CMPF : Op::CMPI, max ? bytecode::kRelLt : bytecode::kRelGt);
    CodeBuilder::Label keep = code_.new_label();
    code_.emit_to(Op::JZ, keep);
    code_.emit(Op::LDL, e);
    code_.emit(Op::STL, acc);
    code_.bind(keep);
    release(1);
  }
  code_.emit(Op::INCL, i, 1);
  code_.emit_to(Op::JMP, top);
  code_.bind(done);
  emit_phase_yields(n, 40);
  code_.emit(Op::LDL, acc);
  release(4);
  return f ? Ty::Float : Ty::Int;
}

}  // namespace uprog::pdl
