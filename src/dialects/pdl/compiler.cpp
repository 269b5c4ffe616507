// The compiler's tokens, diagnostics and program structure: declarations, tasks, procedures
// (VM routines, their frames on the task stack), scopes, and what is resolved at the end
// (return sites, indirect gotos, entry routines).
#include "dialects/pdl/compiler.h"

#include <algorithm>

#include "vm/run_error.h"

namespace uprog::pdl {
namespace {

constexpr size_t kMaxNameLength = 17;
constexpr size_t kMaxLabelLength = 24;

constexpr std::string_view kKeywords[] = {
    "if",     "else",   "do",       "end",   "while",  "loop",   "till",   "goto",      "call",
    "ret",    "halt",   "exitproc", "proc",  "wait",   "sleep",  "lock",   "unlock",    "run",
    "kill",   "level",  "reset",    "seton", "setoff", "toggle", "printl", "retprintl", "sttovar",
    "sizeof", "TOUT",   "long",     "short", "float",  "max",    "min",    "abs",       "sign",
    "sin",    "cos",    "sqrt",     "divi",  "shift",  "bitset", "bitclr", "bittog",    "memcpy",
    "memset", "memmin", "memmax",   "memsum"};

// The first `count` locals of an entry routine; a procedure's routine has as many as it uses.
std::vector<bytecode::Local> entry_locals(uint32_t count = kEntryLocals) {
  static constexpr const char* kNames[] = {"sp", "limit", "base", "fp", "ret", "goto"};
  std::vector<bytecode::Local> out;
  for (uint32_t i = 0; i < count; ++i) {
    bytecode::Local l;
    l.name = i < kFirstScratch ? kNames[i] : "s" + std::to_string(i - kFirstScratch);
    out.push_back(l);
  }
  return out;
}

}  // namespace

Compiler::Compiler(std::vector<Token> tokens, std::function<Location(size_t)> locate,
                   std::string source_name)
    : toks_(std::move(tokens)), locate_(std::move(locate)), source_name_(std::move(source_name)) {
  bytecode::Routine start;
  start.name = "(start)";
  start.kind = bytecode::RoutineKind::Function;
  start.inputs = kEntryInputs;
  start.locals = entry_locals();
  image_.routines.push_back(start);
}

// --- tokens and diagnostics

const Token& Compiler::peek(size_t ahead) const {
  const size_t i = std::min(pos_ + ahead, toks_.size() - 1);
  return toks_[i];
}

const Token& Compiler::next() {
  const Token& t = toks_[pos_];
  if (pos_ + 1 < toks_.size()) ++pos_;
  return t;
}

bool Compiler::at_op(std::string_view op, size_t ahead) const {
  const Token& t = peek(ahead);
  return t.kind == Tok::Op && t.text == op;
}

bool Compiler::at_word(std::string_view word, size_t ahead) const {
  const Token& t = peek(ahead);
  return t.kind == Tok::Name && equal_ignoring_case(t.text, word);
}

bool Compiler::accept_op(std::string_view op) {
  if (!at_op(op)) return false;
  next();
  return true;
}

bool Compiler::accept_word(std::string_view word) {
  if (!at_word(word)) return false;
  next();
  return true;
}

bool Compiler::expect_op(std::string_view op) {
  if (accept_op(op)) return true;
  const Token& t = peek();
  error(Error::Expected, t.offset,
        "'" + std::string(op) + "' before '" + (t.kind == Tok::End ? "end of file" : t.text) + "'");
  return false;
}

std::string Compiler::expect_name() {
  if (peek().kind == Tok::Name) return next().text;
  error(Error::Expected, peek().offset, "a name before '" + peek().text + "'");
  return {};
}

void Compiler::error(Error e, size_t offset, std::string_view detail) {
  if (expression_abandoned_ && e == Error::Expected) return;  // after [pdl 67] in this expression
  if (!is_warning(e)) {
    ++error_count_;
    if (error_count_ > 30) return;
  }
  diagnostics_.push_back(make_diagnostic(e, locate_(offset), detail));
}

bool Compiler::is_keyword(std::string_view name) const {
  for (std::string_view k : kKeywords)
    if (equal_ignoring_case(k, name)) return true;
  return find_system_variable(name) != nullptr || find_state(name) != nullptr;
}

// After an error: on to the next `;` or the next line, so that later errors are reported too.
void Compiler::skip_to_command_end() {
  const size_t from = pos_;
  while (peek().kind != Tok::End) {
    if (at_op(";")) {
      next();
      return;
    }
    if (pos_ != from && peek().line_start) return;
    next();
  }
}

// --- structure

bool Compiler::compile(bytecode::Image& out) {
  program();
  code_.emit(Op::RET);  // the end of the code ends the task
  emit_return_dispatch(0);
  emit_indirect_stubs(0);
  for (const LabelValue& v : label_values_)
    image_.constants[v.constant].bits = scopes_[static_cast<size_t>(v.scope)][v.label].slot;
  for (auto& [name, proc] : procs_) {
    if (!proc.defined) error(Error::ProcNotImplemented, proc.declared_at, name);
  }
  if (!code_.finish())
    error(Error::UnknownLabel, toks_.back().offset, "a jump to a label never defined");
  for (auto& [name, proc] : procs_) {
    if (proc.defined && code_.bound(proc.entry))
      image_.routines[static_cast<size_t>(proc.routine)].entry = code_.target(proc.entry);
  }
  for (auto& [name, info] : scopes_[0]) {
    if (info.routine >= 0 && info.defined)
      image_.routines[static_cast<size_t>(info.routine)].entry = code_.target(info.label);
  }
  if (error_count_ == 0) {
    for (ProcMark& m : proc_marks_) {
      m.info.first = code_.target(m.entry);
      m.info.end = code_.target(m.after);
      debug_info_.procs.push_back(m.info);
    }
    for (const CodeBuilder::Label& site : return_sites_)
      debug_info_.return_sites.push_back(code_.target(site));
    for (const auto& [body, exit] : loop_marks_)
      debug_info_.loops.push_back({code_.target(body), code_.target(exit)});
  }
  // The free user memory and the tasks' stacks follow the variables, each stack at its address
  // (layout.h), so that addresses count words from the first variable (1.3) and LDM/STM reach
  // every word.
  if (user_words_ < kUserWords)
    image_.globals.push_back(
        {"(free)", ValueType::Int, static_cast<uint32_t>(kUserWords - user_words_)});
  int32_t end = kUserWords;
  for (uint32_t t = 1; t <= kTasks; ++t) {
    image_.globals.push_back(
        {"(unused)", ValueType::Int, static_cast<uint32_t>(stack_base(t) - end)});
    image_.globals.push_back(
        {"(stack " + std::to_string(t) + ")", ValueType::Int, static_cast<uint32_t>(kStackWords)});
    end = stack_base(t) + kStackWords;
  }
  image_.dialect = "pdl";
  out = std::move(image_);
  return error_count_ == 0;
}

void Compiler::program() {
  statement_list(0, false);
  while (peek().kind != Tok::End) {
    error(Error::StrayEnd, peek().offset, peek().text);
    next();
    accept_op(";");
    statement_list(0, false);
  }
  finish_scope();
}

bool Compiler::at_block_end() const {
  return peek().kind == Tok::End || at_word("end") || (at_word("else") && at_word("do", 1));
}

void Compiler::statement_list(int depth, bool in_proc) {
  while (!at_block_end()) {
    const size_t before = pos_;
    command(depth, in_proc);
    if (pos_ == before) next();  // never stuck
  }
}

void Compiler::directive() {
  const size_t at = next().offset;  // '#'
  const Token& word = peek();
  if (equal_ignoring_case(word.text, "long")) return next(), declaration(Kind::Long);
  if (equal_ignoring_case(word.text, "short")) return next(), declaration(Kind::Short);
  if (equal_ignoring_case(word.text, "float")) return next(), declaration(Kind::Float);
  if (equal_ignoring_case(word.text, "task")) return next(), task_directive(at);
  error(Error::UnknownDirective, word.offset, "#" + word.text);
  skip_to_command_end();
}

void Compiler::task_directive(size_t at) {
  if (!expect_op("/")) return skip_to_command_end();
  const Token& n = next();
  accept_op(";");
  if (current_proc_ != nullptr) return error(Error::ProcInsideProc, at, "#task inside a procedure");
  if (n.kind != Tok::Int || n.int_value < 1 || n.int_value > static_cast<int32_t>(kTasks)) {
    return error(Error::BadTaskNumber, n.offset, n.text);
  }
  const uint32_t task = static_cast<uint32_t>(n.int_value);
  if (tasks_seen_[task]) return error(Error::TaskTwice, at, "#task/" + n.text);
  tasks_seen_[task] = true;
  in_lock_ = false;  // another task's code: the lock above is not its own (2.2.2)
  bytecode::Routine r;
  r.name = "task " + std::to_string(task);
  r.kind = bytecode::RoutineKind::Task;
  r.inputs = kEntryInputs;
  r.locals = entry_locals();
  r.entry = code_.here();
  image_.routines.push_back(r);
  bytecode::Task rec;
  rec.routine = static_cast<uint32_t>(image_.routines.size() - 1);
  rec.number = task;
  rec.starts_at_reset = true;
  image_.tasks.push_back(rec);
}

void Compiler::declaration(Kind kind) {
  bool read_only = false;
  int32_t level_read = 0, level_write = 0;
  while (true) {
    if (accept_word("_ro")) {
      read_only = true;
    } else if (at_word("_lp")) {
      next();
      expect_op("(");
      level_read = peek().kind == Tok::Int ? next().int_value : 0;
      expect_op(",");
      level_write = peek().kind == Tok::Int ? next().int_value : 0;
      expect_op(")");
    } else {
      break;
    }
  }
  bool first = true;
  while (true) {
    if (!first) {
      if (!accept_op(",")) break;
    }
    first = false;
    const bool pointer = accept_op("*");
    const Token& name = peek();
    if (name.kind != Tok::Name) {
      error(Error::Expected, name.offset, "a variable name");
      return skip_to_command_end();
    }
    next();
    uint32_t length = 1;
    if (accept_op("[")) {
      const Token& n = next();
      if (n.kind != Tok::Int || n.int_value < 1 || n.int_value > kUserWords) {
        error(Error::ArrayTooLarge, n.offset, n.text);
      } else {
        length = static_cast<uint32_t>(n.int_value);
      }
      expect_op("]");
    }
    if (name.text.size() > kMaxNameLength) error(Error::NameTooLong, name.offset, name.text);
    if (is_keyword(name.text)) {
      error(Error::ReservedName, name.offset, name.text);
      continue;
    }
    Var v;
    v.name = name.text;
    v.kind = kind;
    v.pointer = pointer;
    v.length = length;
    if (kind == Kind::Short && pointer) {
      error(Error::ShortPointer, name.offset, name.text);
      continue;
    }
    if (current_proc_ != nullptr) {
      if (kind == Kind::Short) error(Error::ShortLocal, name.offset, name.text);
      for (const Var& l : locals_)
        if (l.name == v.name) error(Error::Redefined, name.offset, v.name);
      v.local = true;
      v.address = frame_words_;
      frame_words_ += static_cast<int32_t>(length);
      if (frame_words_ > kStackWords)
        error(Error::StackFrameTooLarge, name.offset, current_proc_->name);
      locals_.push_back(v);
      continue;
    }
    for (const Var& g : globals_)
      if (g.name == v.name) error(Error::Redefined, name.offset, v.name);
    if (procs_.count(v.name)) error(Error::Redefined, name.offset, v.name);
    v.address = user_words_;
    user_words_ += static_cast<int32_t>(length);
    if (user_words_ > kUserWords) {
      error(Error::MemoryFull, name.offset,
            v.name + " ends at word " + std::to_string(user_words_));
      user_words_ -= static_cast<int32_t>(length);
      continue;
    }
    v.global = static_cast<int32_t>(image_.globals.size());
    image_.globals.push_back(
        {v.name, kind == Kind::Float && !pointer ? ValueType::Float : ValueType::Int, length});
    // What the host protocol needs beyond the globals table: the kind, _ro and _lp.
    const char* kind_name = pointer               ? (kind == Kind::Float ? "fptr" : "lptr")
                            : kind == Kind::Short ? "short"
                            : kind == Kind::Float ? "float"
                                                  : "long";
    image_.info.push_back("var " + v.name + " " + kind_name + " " + (read_only ? "1" : "0") + " " +
                          std::to_string(level_read) + " " + std::to_string(level_write));
    globals_.push_back(v);
    // A declaration ends at ';' or at the end of its line.
    if (peek().line_start && !at_op(",")) break;
  }
  accept_op(";");
}

void Compiler::procedure() {
  const size_t at = next().offset;  // proc
  const Token& name = peek();
  if (name.kind != Tok::Name) {
    error(Error::Expected, name.offset, "a procedure name");
    return skip_to_command_end();
  }
  next();
  if (current_proc_ != nullptr) error(Error::ProcInsideProc, at, name.text);
  if (name.text.size() > kMaxLabelLength) error(Error::LabelTooLong, name.offset, name.text);
  if (is_keyword(name.text)) error(Error::ReservedName, name.offset, name.text);
  std::vector<Param> params;
  expect_op("(");
  while (!at_op(")") && peek().kind != Tok::End) {
    Param p;
    const Token& type = next();
    if (equal_ignoring_case(type.text, "long"))
      p.kind = Kind::Long;
    else if (equal_ignoring_case(type.text, "float"))
      p.kind = Kind::Float;
    else if (!equal_ignoring_case(type.text, "short"))
      error(Error::Expected, type.offset, "long or float before '" + type.text + "'");
    p.pointer = accept_op("*");
    if (equal_ignoring_case(type.text, "short")) {
      error(p.pointer ? Error::ShortPointer : Error::ShortLocal, type.offset, "parameter");
    }
    const Token& param = peek();
    p.name = expect_name();
    // A parameter is a local variable (1.4): a variable's name, never a system one's.
    if (p.name.size() > kMaxNameLength) error(Error::NameTooLong, param.offset, p.name);
    if (!p.name.empty() && is_keyword(p.name)) error(Error::ReservedName, param.offset, p.name);
    params.push_back(p);
    if (!accept_op(",")) break;
  }
  expect_op(")");
  Proc& proc = proc_named(name.text, params, name.offset);
  if (accept_op(";")) return;  // a prototype
  if (!accept_word("do")) {
    if (peek().line_start || peek().kind == Tok::End) return;  // a prototype without ';'
    error(Error::Expected, peek().offset, "do or ';' after the procedure's head");
    return skip_to_command_end();
  }
  if (proc.defined) error(Error::Redefined, name.offset, "procedure " + name.text);
  if (current_proc_ != nullptr) {
    // Its body still closes with its own end, so that the outer procedure's stays its own.
    proc.defined = true;
    statement_list(1, true);
    accept_word("end");
    accept_op(";");
    return;
  }
  proc.defined = true;
  CodeBuilder::Label after = code_.new_label();
  code_.emit_to(Op::JMP, after);  // the code around it does not fall into it
  current_proc_ = &proc;
  scopes_.emplace_back();
  scope_ = static_cast<int>(scopes_.size() - 1);
  locals_.clear();
  frame_words_ = 2;  // the words a return id and a saved fp took: reserved, as pdl-drive.md counts
  for (const Param& p : params) {
    Var v;
    v.name = p.name;
    v.kind = p.kind;
    v.pointer = p.pointer;
    v.local = true;
    v.address = frame_words_++;
    locals_.push_back(v);
  }
  scratch_high_ = kFirstScratch;
  const int loops_outside = loop_depth_;
  loop_depth_ = 0;  // the procedure's own stack frame: no loop of the caller's is in it
  proc_end_ = code_.new_label();
  // The caller's CALLFEOL checked the frame's room, stored the arguments and set the locals to 0
  // (compiler_commands.cpp, proc_call).
  code_.bind(proc.entry);
  statement_list(1, true);
  if (accept_word("end")) {
    begin_command(1);
    proc_return();
    accept_op(";");
  } else {
    error(Error::UnclosedBlock, at, "procedure " + name.text);
  }
  code_.bind(proc_end_);
  code_.emit(Op::RET);
  if (dispatchers_.count(scope_)) emit_return_dispatch(scope_);
  emit_indirect_stubs(scope_);
  proc.frame_words = frame_words_;
  const uint32_t shape = frame_shape(proc.frame_words, static_cast<int32_t>(params.size()));
  for (uint32_t at_word : proc.frame_patches) image_.code[at_word + 1] = shape;
  proc.frame_patches.clear();
  image_.routines[static_cast<size_t>(proc.routine)].locals = entry_locals(scratch_high_);
  finish_scope();
  ProcMark mark{
      {proc.name, 0, 0, frame_words_, static_cast<uint32_t>(params.size()), {}}, proc.entry, after};
  for (const Var& v : locals_) {
    const char kind = v.kind == Kind::Float ? 'f' : v.kind == Kind::Short ? 's' : 'l';
    mark.info.vars.push_back({v.name, kind, v.pointer, v.length, v.address});
  }
  proc_marks_.push_back(std::move(mark));
  scope_ = 0;
  loop_depth_ = loops_outside;
  current_proc_ = nullptr;
  locals_.clear();
  code_.bind(after);
}

// A procedure by its head, made on its first prototype or definition with its routine (a
// prototype's calls need the routine's number); a head that differs from the first is [pdl 86].
Proc& Compiler::proc_named(const std::string& name, const std::vector<Param>& params,
                           size_t offset) {
  auto found = procs_.find(name);
  if (found != procs_.end()) {
    if (found->second.params != params) error(Error::PrototypeMismatch, offset, name);
    return found->second;
  }
  Proc& proc = procs_[name];
  proc.name = name;
  proc.params = params;
  proc.entry = code_.new_label();
  proc.declared_at = offset;
  bytecode::Routine r;
  r.name = "proc " + name;  // not a label's name: `run`, `--entry` and function breakpoints skip it
  r.kind = bytecode::RoutineKind::Function;
  r.inputs = kEntryInputs;
  r.locals = entry_locals();
  image_.routines.push_back(r);
  proc.routine = static_cast<int>(image_.routines.size() - 1);
  return proc;
}

void Compiler::finish_scope() {
  for (auto& [name, info] : scopes_[static_cast<size_t>(scope_)]) {
    if (!info.defined) {
      error(Error::UnknownLabel, info.first_use, name);
      code_.bind(info.label);  // keeps the jumps patchable; the image is not kept
      info.defined = true;
    }
  }
  patch_loop_exits(scope_);
}

LabelInfo& Compiler::label_named(const std::string& name, int scope, size_t offset) {
  auto& labels = scopes_[static_cast<size_t>(scope)];
  auto it = labels.find(name);
  if (it != labels.end()) return it->second;
  LabelInfo& info = labels[name];
  info.label = code_.new_label();
  info.first_use = offset;
  return info;
}

// Every global label is an entry routine: `run` and the host start tasks there.
int Compiler::routine_for_label(const std::string& name, size_t offset) {
  LabelInfo& info = label_named(name, 0, offset);
  if (info.routine < 0) {
    bytecode::Routine r;
    r.name = name;
    r.kind = bytecode::RoutineKind::Label;
    r.inputs = kEntryInputs;
    r.locals = entry_locals();
    image_.routines.push_back(r);
    info.routine = static_cast<int>(image_.routines.size() - 1);
  }
  return info.routine;
}

void Compiler::emit_dispatch(uint32_t local,
                             const std::vector<std::pair<int32_t, CodeBuilder::Label>>& cases) {
  if (cases.size() <= 4) {
    for (const auto& [key, target] : cases) {
      code_.emit(Op::LDL, local);
      push_int(key);
      code_.emit_to(Op::JEQI, target);
    }
    code_.emit(Op::RAISE, static_cast<uint32_t>(vm::RunError::IndexOutOfRange));
    return;
  }
  const size_t mid = cases.size() / 2;
  CodeBuilder::Label right = code_.new_label();
  code_.emit(Op::LDL, local);
  push_int(cases[mid].first);
  code_.emit_to(Op::JGEI, right);
  emit_dispatch(local, {cases.begin(), cases.begin() + static_cast<std::ptrdiff_t>(mid)});
  code_.bind(right);
  emit_dispatch(local, {cases.begin() + static_cast<std::ptrdiff_t>(mid), cases.end()});
}

CodeBuilder::Label Compiler::dispatch_label(int scope) {
  auto it = dispatchers_.find(scope);
  if (it == dispatchers_.end()) it = dispatchers_.emplace(scope, code_.new_label()).first;
  return it->second;
}

// `ret` and the end of a `call`ed label: back to a return site of the scope's own `call`s (a
// procedure's routine jumps only within itself).
void Compiler::emit_return_dispatch(int scope) {
  code_.bind(dispatch_label(scope));
  std::vector<std::pair<int32_t, CodeBuilder::Label>> cases;
  for (size_t i = 0; i < return_sites_.size(); ++i)
    if (return_scopes_[i] == scope) cases.push_back({static_cast<int32_t>(i), return_sites_[i]});
  emit_dispatch(kRetId, cases);
}

// `goto L[n]`: n counts slots from L; only a command's start in L's scope is a target.
void Compiler::emit_indirect_stubs(int scope) {
  for (const IndirectGoto& g : indirect_) {
    if (g.scope != scope) continue;
    line_entry(g.offset);  // an n that is no command's start is the goto's error
    code_.bind(g.stub);
    auto& labels = scopes_[static_cast<size_t>(g.scope)];
    auto it = labels.find(g.label);
    std::vector<std::pair<int32_t, CodeBuilder::Label>> cases;
    struct Trampoline {
      CodeBuilder::Label from, to;
      int drop;
    };
    std::vector<Trampoline> exits;  // a target outside loops around the goto (emit_loop_exit())
    if (it != labels.end()) {
      for (const CommandStart& c : commands_) {
        if (c.scope != g.scope || c.slot < it->second.slot) continue;
        const int32_t offset = static_cast<int32_t>(c.slot - it->second.slot);
        if (!cases.empty() && cases.back().first == offset) continue;
        CodeBuilder::Label target = c.label;
        if (g.loop_depth > c.loop_depth) {
          target = code_.new_label();
          exits.push_back({target, c.label, g.loop_depth - c.loop_depth});
        }
        cases.push_back({offset, target});
      }
    }
    emit_dispatch(kGotoN, cases);
    for (const Trampoline& e : exits) {
      code_.bind(e.from);
      code_.emit(Op::INCL, kSp, static_cast<uint32_t>(-e.drop));
      code_.emit_to(Op::JMP, e.to);
    }
  }
}

void Compiler::patch_loop_exits(int scope) {
  for (const LoopExit& e : loop_exits_) {
    if (e.scope != scope) continue;
    const int target = scopes_[static_cast<size_t>(scope)][e.label].loop_depth;
    if (e.depth > target) image_.code[e.code + 1] = static_cast<uint32_t>(target - e.depth);
  }
}

// --- the debugger's evaluations

bool Compiler::compile_evaluation(EvalForm form, std::vector<Var> globals, std::vector<Var> locals,
                                  const std::vector<bytecode::Global>& image_globals,
                                  bytecode::Image& out, bool& is_float) {
  strict_forms_ = false;  // the debugger evaluates expressions of any shape
  globals_ = std::move(globals);
  locals_ = std::move(locals);
  // The program's globals as they are, so that LDG/STG and LDM/STM reach the same words.
  image_.globals = image_globals;
  const auto result = static_cast<uint32_t>(image_.globals.size());
  image_.globals.push_back({"(result)", ValueType::Int, 1});
  if (form == EvalForm::Assignment) {
    assignment();
    pos_ = 0;  // then its left side's value
  }
  Ty type = Ty::Int;
  if (form == EvalForm::Condition) {
    condition();
  } else {
    type = expr();
  }
  if (form != EvalForm::Assignment && peek().kind != Tok::End)
    error(Error::Syntax, peek().offset, "'" + peek().text + "' does not continue the expression");
  is_float = type == Ty::Float;
  code_.emit(Op::STG, result);
  code_.emit(Op::RET);
  if (!code_.finish()) error(Error::Syntax, 0, "a jump to a label never defined");
  image_.dialect = "pdl";
  out = std::move(image_);
  return error_count_ == 0;
}

}  // namespace uprog::pdl
