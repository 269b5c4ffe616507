// The compiler's commands (2.2, 2.4): each records where it starts (for `goto L[n]` and the line
// table), counts its slots, and ends its phase with EOL, so that the phase scheduler runs one
// command per turn; the few that take several phases yield inside.
#include <cctype>

#include "dialects/pdl/compiler.h"
#include "vm/run_error.h"

namespace uprog::pdl {

void Compiler::line_entry(size_t offset) {
  const Location where = locate_(offset);
  bytecode::LineEntry e{code_.here(), where.file.empty() ? source_name_ : where.file,
                        static_cast<uint32_t>(where.line < 0 ? 0 : where.line)};
  if (!image_.lines.empty() && image_.lines.back().code == e.code)
    image_.lines.back() = e;
  else
    image_.lines.push_back(e);
}

void Compiler::begin_command(uint32_t slots, std::optional<size_t> offset) {
  if (!in_short_if_) {
    line_entry(offset.value_or(peek().offset));
    const CodeBuilder::Label start = code_.new_label();
    code_.bind(start);
    commands_.push_back({slots_, start, scope_, loop_depth_});
  }
  slots_ += slots;
  check_code_size();
}

// 1.1: code up to 32 KB (4 bytes a slot, the printl strings with their NULs).
void Compiler::check_code_size() {
  if (size_reported_ || slots_ * 4 + text_bytes_ <= kPdlCodeBytes) return;
  size_reported_ = true;
  error(Error::CodeTooLarge, peek().offset, std::to_string(slots_ * 4 + text_bytes_) + " bytes");
}

// A constant argument: a number, or a negated one.
bool Compiler::is_literal(size_t first, size_t end) const {
  auto number = [&](size_t i) {
    return toks_[i].kind == Tok::Int || toks_[i].kind == Tok::Float || toks_[i].kind == Tok::Char;
  };
  if (end == first + 1) return number(first);
  return end == first + 2 && toks_[first].kind == Tok::Op && toks_[first].text == "-" &&
         number(first + 1);
}

void Compiler::command(int depth, bool in_proc) {
  const Token& t = peek();
  if (at_op(";")) return (void)next();
  if (at_op("#")) return directive();
  if (t.kind == Tok::Name && at_op(":", 1) && !is_keyword(t.text)) {
    next();
    next();
    if (t.text.size() > 24) error(Error::LabelTooLong, t.offset, t.text);
    if (scope_ == 0) routine_for_label(t.text, t.offset);
    LabelInfo& info = label_named(t.text, scope_, t.offset);
    if (info.defined) return error(Error::LabelRedefined, t.offset, t.text);
    info.defined = true;
    info.slot = slots_;
    info.loop_depth = loop_depth_;
    code_.bind(info.label);
    return;
  }
  if (at_word("proc")) return procedure();
  if (at_word("if")) return if_command(depth, in_proc);
  if (at_word("while")) return while_command(depth, in_proc);
  if (at_word("loop")) return loop_command(depth, in_proc);
  if (at_word("till")) return till_command();
  if (at_word("wait")) return wait_command();
  const bool ends_task =
      depth == 0 && !in_proc && (at_word("halt") || at_word("ret") || at_word("retprintl"));
  simple_command(in_proc);
  // The task ends here, and its lock with it (pdl-drive.md): what follows is another entry's.
  if (ends_task) in_lock_ = false;
}

// The commands a short `if` may hold (2.2.8), and every other one-line command.
void Compiler::simple_command(bool in_proc) {
  const Token& t = peek();
  const size_t errors_before = error_count_;
  if (at_word("goto"))
    goto_command();
  else if (at_word("call"))
    call_command();
  else if (at_word("ret"))
    ret_command();
  else if (at_word("halt")) {
    next();
    begin_command(1);
    end_line();
    code_.emit(Op::EXIT);
  } else if (at_word("exitproc")) {
    next();
    if (!in_proc) error(Error::ExitprocOutside, t.offset);
    begin_command(1);
    proc_return();
  } else if (at_word("lock") || at_word("unlock")) {
    const bool lock = at_word("lock");
    next();
    begin_command(1);
    code_.emit(Op::CMDRUN, lock ? kLockCommand : kUnlockCommand, 0);
    end_line();
    in_lock_ = lock;
  } else if (at_word("run"))
    run_command();
  else if (at_word("kill"))
    kill_command();
  else if (at_word("seton"))
    set_state_command(1);
  else if (at_word("setoff"))
    set_state_command(0);
  else if (at_word("toggle"))
    set_state_command(2);
  else if (at_word("printl"))
    printl_command(false);
  else if (at_word("retprintl"))
    printl_command(true);
  else if (at_word("sleep"))
    sleep_command();
  else if (at_word("wait") || at_word("till") || at_word("if") || at_word("while") ||
           at_word("loop")) {
    error(Error::ShortIfCommand, t.offset, t.text);
    next();
  } else if (t.kind == Tok::Name && at_op("(", 1) && !is_keyword(t.text)) {
    auto it = procs_.find(t.text);
    if (it == procs_.end()) {
      error(Error::UnknownProc, t.offset, t.text);
      skip_to_command_end();
      return;
    }
    next();
    proc_call(it->second);
  } else if (t.kind == Tok::Name || at_op("*")) {
    assignment();
  } else {
    error(Error::Syntax, t.offset, "unexpected '" + t.text + "'");
    next();
  }
  if (error_count_ != errors_before) return skip_to_command_end();
  accept_op(";");
}

// A short if's command: one slot, or more (then the test takes a phase of its own).
uint32_t Compiler::short_command_slots() {
  if (at_word("printl") || at_word("retprintl")) return 2;
  const Token& t = peek();
  if (t.kind == Tok::Name && at_op("(", 1) && procs_.count(t.text)) return at_op(")", 2) ? 1 : 2;
  for (size_t k = 0; k < 64; ++k) {
    const Token& a = peek(k);
    if (a.kind == Tok::End || (a.kind == Tok::Op && a.text == ";") || (k > 0 && a.line_start))
      break;
    if (a.kind == Tok::Op && a.text == "=") {
      const Token& b = peek(k + 1);
      return (b.kind == Tok::Op && b.text == "{") || b.kind == Tok::String ? 2 : 1;
    }
  }
  return 1;
}

void Compiler::if_command(int depth, bool in_proc) {
  const size_t at = next().offset;
  if (depth >= 200) error(Error::NestingTooDeep, at);
  begin_command(1);
  expect_op("(");
  CodeBuilder::Label f = code_.new_label(), end = code_.new_label();
  jump_on_condition(false, f);
  expect_op(")");
  if (accept_word("do")) {
    end_line();
    statement_list(depth + 1, in_proc);
    if (at_word("else") && at_word("do", 1)) {
      // `else do` is a command of its own line: the then-branch's jump past the else-branch.
      const size_t else_at = next().offset;
      next();
      begin_command(1, else_at);
      code_.emit_to(Op::JMP, end);
      code_.bind(f);
      end_line();
      statement_list(depth + 1, in_proc);
    } else {
      code_.emit_to(Op::JMP, end);
      code_.bind(f);
      end_line();
    }
    if (!accept_word("end")) error(Error::UnclosedBlock, at, "if");
    accept_op(";");
    code_.bind(end);
    return;
  }
  // 2.2.8 a: the test and a one-slot command share a phase.
  const uint32_t slots = short_command_slots();
  if (slots > 1) end_line();
  in_short_if_ = true;
  simple_command(in_proc);
  in_short_if_ = false;
  code_.emit_to(Op::JMP, end);
  code_.bind(f);
  end_line();
  code_.bind(end);
  if (at_word("else") && !at_word("do", 1))
    error(Error::StrayEnd, peek().offset, "else after a short if");
}

void Compiler::while_command(int depth, bool in_proc) {
  const size_t at = next().offset;
  if (depth >= 200) error(Error::NestingTooDeep, at);
  begin_command(1);
  CodeBuilder::Label top = code_.new_label(), f = code_.new_label();
  code_.bind(top);
  expect_op("(");
  jump_on_condition(false, f);
  expect_op(")");
  if (!accept_word("do")) error(Error::Expected, peek().offset, "do after while's condition");
  end_line();
  statement_list(depth + 1, in_proc);
  if (!accept_word("end")) error(Error::UnclosedBlock, at, "while");
  begin_command(1);
  code_.emit_to(Op::JMP, top);  // no phase of its own: the test takes it
  accept_op(";");
  code_.bind(f);
  end_line();
}

// A loop's count is a word on the task's stack (2.2.7): its low 16 bits, 0 meaning 65536.
void Compiler::loop_command(int depth, bool in_proc) {
  const size_t at = next().offset;
  if (depth >= 200) error(Error::NestingTooDeep, at);
  begin_command(1);
  expect_op("(");
  int_operand(expr(), at);
  expect_op(")");
  if (!accept_word("do")) error(Error::Expected, peek().offset, "do after loop's count");
  const uint32_t s = scratch();
  code_.emit(Op::ZEXT, 16);
  code_.emit(Op::STL, s);
  code_.emit(Op::LDL, kSp);
  code_.emit(Op::LDL, kLimit);
  CodeBuilder::Label room = code_.new_label();
  code_.emit_to(Op::JLTI, room);
  code_.emit(Op::RAISE, static_cast<uint32_t>(vm::RunError::CallDepth));
  code_.bind(room);
  code_.emit(Op::LDL, kSp);
  code_.emit(Op::LDL, s);
  code_.emit(Op::STM);
  code_.emit(Op::INCL, kSp, 1);
  release(1);
  end_line();
  CodeBuilder::Label body = code_.new_label(), exit = code_.new_label();
  code_.bind(body);
  ++loop_depth_;
  statement_list(depth + 1, in_proc);
  --loop_depth_;
  if (!accept_word("end")) error(Error::UnclosedBlock, at, "loop");
  begin_command(1);
  loop_end(body, exit);
  code_.bind(exit);
  loop_marks_.push_back({body, exit});
  code_.emit(Op::INCL, kSp, static_cast<uint32_t>(-1));
  end_line();
  accept_op(";");
}

// The count, the word below sp, less one: while it stays above 0, back to the body; at 0, out;
// below 0 (a count of 0 is 65536, 2.2.7) it becomes 65535 and the body runs again. Its word
// stays within 0..65535 as the 16-bit count. The usual turn is two instructions once fused at
// load (STEPMLK, JRELMK) and the jump back that ends the line.
void Compiler::loop_end(CodeBuilder::Label body, CodeBuilder::Label exit) {
  const auto count_word = [&] { emit_stack_address(kSp, -1); };
  count_word();
  code_.emit(Op::LDM);
  push_int(1);
  code_.emit(Op::SUBI);
  count_word();
  code_.emit(Op::SWAP);
  code_.emit(Op::STM);
  CodeBuilder::Label spent = code_.new_label();
  count_word();
  code_.emit(Op::LDM);
  push_int(0);
  code_.emit_to(Op::JLEI, spent);
  end_line();
  code_.emit_to(Op::JMP, body);
  code_.bind(spent);
  count_word();
  code_.emit(Op::LDM);
  push_int(0);
  code_.emit_to(Op::JEQI, exit);
  count_word();
  push_int(65535);
  code_.emit(Op::STM);
  end_line();
  code_.emit_to(Op::JMP, body);
}

void Compiler::till_command() {
  next();
  begin_command(1);
  CodeBuilder::Label top = code_.new_label(), done = code_.new_label();
  code_.bind(top);
  expect_op("(");
  jump_on_condition(true, done);
  expect_op(")");
  code_.emit(Op::YIELD);  // the test spent this turn
  code_.emit_to(Op::JMP, top);
  code_.bind(done);
  end_line();
  accept_op(";");
}

// `wait n`: n phases, the command's own included, each turn a test of the phase counter.
void Compiler::wait_command() {
  const size_t at = next().offset;
  begin_command(1);
  const uint32_t n = scratch(), t0 = scratch();
  int_operand(expr(), at);
  code_.emit(Op::STL, n);
  code_.emit(Op::CMDGET, system_variable_by_id(14)->id, 0);  // fclk
  code_.emit(Op::STL, t0);
  CodeBuilder::Label top = code_.new_label(), done = code_.new_label();
  code_.bind(top);
  code_.emit(Op::CMDGET, 14, 0);
  code_.emit(Op::LDL, t0);
  code_.emit(Op::SUBI);
  code_.emit(Op::LDL, n);
  push_int(1);
  code_.emit(Op::SUBI);
  code_.emit_to(Op::JGEI, done);
  code_.emit(Op::YIELD);
  code_.emit_to(Op::JMP, top);
  code_.bind(done);
  release(2);
  end_line();
  accept_op(";");
}

// `sleep n`: its phase, then n ms out of turn (WAIT counts microseconds).
void Compiler::sleep_command() {
  const size_t at = next().offset;
  if (in_lock_) error(Error::SleepInLock, at);
  begin_command(1);
  int_operand(expr(), at);
  code_.emit(Op::WAIT, 1000);
  end_line();
}

void Compiler::goto_command() {
  next();
  begin_command(1);
  const Token& name = peek();
  const std::string label = expect_name();
  if (label.empty()) return;
  if (scope_ == 0) routine_for_label(label, name.offset);
  LabelInfo& info = label_named(label, scope_, name.offset);
  if (accept_op("[")) {
    int_operand(expr(), name.offset);
    expect_op("]");
    code_.emit(Op::STL, kGotoN);
    end_line();
    IndirectGoto g{scope_, label, code_.new_label(), name.offset, loop_depth_};
    code_.emit_to(Op::JMP, g.stub);
    indirect_.push_back(g);
    return;
  }
  emit_loop_exit(label);
  end_line();
  code_.emit_to(Op::JMP, info.label);
}

// A goto out of loops drops their counts from the task's stack, as their ends would have:
// without it, each such exit left a word behind, and the task's stack overflowed after 256.
// The label's loops are known once it is defined; compile() patches the count in then.
void Compiler::emit_loop_exit(const std::string& label) {
  if (loop_depth_ == 0) return;
  loop_exits_.push_back({code_.here(), scope_, label, loop_depth_});
  code_.emit(Op::INCL, kSp, 0);
}

void Compiler::call_command() {
  next();
  begin_command(1);
  const size_t label_at = peek().offset;
  const std::string label = expect_name();
  if (label.empty()) return;
  if (scope_ == 0) routine_for_label(label, label_at);
  LabelInfo& info = label_named(label, scope_, label_at);
  code_.emit(Op::LDL, kSp);
  code_.emit(Op::LDL, kLimit);
  CodeBuilder::Label room = code_.new_label();
  code_.emit_to(Op::JLTI, room);
  code_.emit(Op::RAISE, static_cast<uint32_t>(vm::RunError::CallDepth));
  code_.bind(room);
  const int32_t id = static_cast<int32_t>(return_sites_.size());
  return_sites_.push_back(code_.new_label());
  return_scopes_.push_back(scope_);
  code_.emit(Op::LDL, kSp);
  push_int(id);
  code_.emit(Op::STM);
  code_.emit(Op::INCL, kSp, 1);
  end_line();
  code_.emit_to(Op::JMP, info.label);
  code_.bind(return_sites_.back());
}

// `ret`: back to the last `call`, or with an empty stack the end of the task (2.2.5).
void Compiler::ret_command() {
  next();
  begin_command(1);
  emit_ret();
}

void Compiler::emit_ret() {
  // A ret inside loops of the called code drops their counts first (emit_loop_exit()).
  if (loop_depth_ > 0) code_.emit(Op::INCL, kSp, static_cast<uint32_t>(-loop_depth_));
  CodeBuilder::Label more = code_.new_label();
  code_.emit(Op::LDL, kSp);
  code_.emit(Op::LDL, kBase);
  code_.emit_to(Op::JNEI, more);
  end_line();
  code_.emit(Op::RET);
  code_.bind(more);
  code_.emit(Op::INCL, kSp, static_cast<uint32_t>(-1));
  code_.emit(Op::LDL, kSp);
  code_.emit(Op::LDM);
  code_.emit(Op::STL, kRetId);
  end_line();
  code_.emit_to(Op::JMP, dispatch_label(scope_));
}

// A procedure's end and exitproc: the VM's RET (the peephole pass makes the line's end and the
// jump to it one RETEOL). The caller's frame registers are its own locals: nothing to restore.
void Compiler::proc_return() {
  end_line();
  code_.emit_to(Op::JMP, proc_end_);
}

// A call: the arguments on the VM's stack, then CALLFEOL, which checks the whole frame's room on
// the task's stack (else CallDepth), stores them into the parameter words after the two reserved
// ones (pdl-drive.md counts them), sets the locals to 0, ends the line and calls with the
// callee's stack registers: sp past its frame, fp at it. A call compiled before the procedure's
// end (its own recursion, or after a prototype) gets the frame's size patched in then.
void Compiler::proc_call(Proc& proc) {
  const size_t at = peek().offset;
  begin_command(1);
  const int32_t params = static_cast<int32_t>(proc.params.size());
  expect_op("(");
  int32_t count = 0;
  while (!at_op(")") && peek().kind != Tok::End) {
    const size_t arg_at = peek().offset;
    const size_t first = pos_;
    const Ty t = expr();
    check_proc_argument(first, pos_);
    const bool constant = is_literal(first, pos_);
    if (count < params) {
      const Param& p = proc.params[static_cast<size_t>(count)];
      const Ty want = p.pointer ? (p.kind == Kind::Float ? Ty::PtrFloat : Ty::PtrInt)
                                : (p.kind == Kind::Float ? Ty::Float : Ty::Int);
      const bool scalar_ok =
          !p.pointer && (t == Ty::Int || t == Ty::Float) && (t == want || constant);
      if (t != want && !scalar_ok) {
        error(Error::ArgumentType, arg_at, "parameter " + p.name + " of " + proc.name);
      }
      convert(t, want, false);
    }
    ++count;
    if (!accept_op(",")) break;
  }
  expect_op(")");
  slots_ += static_cast<uint32_t>(count);
  if (count != params) {
    error(Error::ArgumentCount, at,
          proc.name + " takes " + std::to_string(params) + ", got " + std::to_string(count));
    for (; count > params; --count) code_.emit(Op::POP);
    for (; count < params; ++count) push_int(0);
  }
  if (proc.frame_words < 0) proc.frame_patches.push_back(code_.here());
  code_.emit(Op::CALLFEOL, static_cast<uint32_t>(proc.routine),
             frame_shape(proc.frame_words, params));
}

uint32_t Compiler::frame_shape(int32_t frame_words, int32_t params) {
  const auto words = static_cast<uint32_t>(frame_words < 0 ? kMinFrameWords + params : frame_words);
  return bytecode::pack_memory_frame(words, static_cast<uint32_t>(params), kMinFrameWords);
}

void Compiler::run_command() {
  const size_t at = next().offset;
  begin_command(1);
  if (!expect_op("/")) return;
  const Token& t = next();
  if (t.kind != Tok::Int || t.int_value < 1 || t.int_value > 3)
    error(Error::BadTaskNumber, t.offset, t.text);
  const std::string label = expect_name();
  if (label.empty()) return;
  if (scope_ != 0 && scopes_[static_cast<size_t>(scope_)].count(label)) {
    error(Error::RunNeedsGlobalLabel, at, label);
    return;
  }
  const int routine = routine_for_label(label, at);
  push_int(t.int_value);
  push_int(routine);
  code_.emit(Op::CMDRUNX, kRunCommand, 1);
  end_line();
}

void Compiler::kill_command() {
  next();
  begin_command(1);
  if (!expect_op("/")) return;
  const Token& t = next();
  if (t.kind != Tok::Int || t.int_value < 1 || t.int_value > 3)
    error(Error::BadTaskNumber, t.offset, t.text);
  push_int(t.int_value);
  code_.emit(Op::CMDRUNX, kKillCommand, 0);
  end_line();
}

// seton/setoff/toggle (2.4.3): a named state or `<var>`, the state whose number var holds.
void Compiler::set_state_command(int mode) {
  next();
  begin_command(1);
  const size_t at = peek().offset;
  std::optional<Place> p = parse_place(true);
  if (!p) return;
  if (p->form != Place::Form::State && p->form != Place::Form::StateX) {
    return error(Error::NotAState, at);
  }
  if (mode == 2) {
    emit_load(*p, true);
    code_.emit(Op::LNOT);
  } else {
    push_int(mode);
  }
  emit_store(*p);
  end_line();
}

}  // namespace uprog::pdl
