// The debugger's breakpoints and execution control (debugger.h); frames and variables are in
// inspect.cpp.
#include "debug/debugger.h"

#include <algorithm>

#include "debug/source_lines.h"
#include "dialect/scheduling/report.h"
#include "vm/run_error.h"

namespace uprog::debug {

const char* stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::Entry:
      return "entry";
    case StopReason::Breakpoint:
      return "breakpoint";
    case StopReason::FunctionBreakpoint:
      return "function breakpoint";
    case StopReason::Step:
      return "step";
    case StopReason::Pause:
      return "pause";
    case StopReason::Exception:
      return "exception";
  }
  return "pause";
}

Debugger::Debugger(controller::Controller& drive) : drive_(drive) {}

dialect::LoadedProgram* Debugger::program() const { return drive_.firmware().debug_program(); }

// --- breakpoints ---

void Debugger::resolve(Armed& b) const {
  b.pc.reset();
  b.state.verified = false;
  const dialect::LoadedProgram* p = program();
  if (p == nullptr) {
    b.state.message = "no program is loaded";
    return;
  }
  const bytecode::Image& image = p->image();
  if (!b.spec.function.empty()) {
    const int r = image.find_routine(b.spec.function);
    if (r >= 0) {
      b.pc = image.routines[static_cast<size_t>(r)].entry;
    } else if (const auto pc = drive_.firmware().debug_function_entry(b.spec.function)) {
      b.pc = *pc;
    } else {
      b.state.message = "no function named '" + b.spec.function + "'";
      return;
    }
    if (const bytecode::LineEntry* e = image.line_at(*b.pc)) {
      b.state.file = e->file;
      b.state.line = e->line;
    }
  } else {
    const auto place = resolve_line(image, b.file, b.spec.line);
    if (!place) {
      b.state.message = "no code at or after this line";
      return;
    }
    b.pc = place->pc;
    b.state.file = place->file;
    b.state.line = place->line;
  }
  b.state.verified = true;
  b.state.message.clear();
}

std::vector<BreakpointState> Debugger::states_of(bool functions) const {
  std::vector<BreakpointState> out;
  for (const Armed& b : breakpoints_)
    if (b.spec.function.empty() != functions) out.push_back(b.state);
  return out;
}

Debugger::Armed Debugger::make_breakpoint(std::string file, const BreakpointSpec& spec) {
  Armed b{next_id_++, std::move(file), spec, {}, 0, std::nullopt, {}, false};
  b.state.id = b.id;
  std::string error;
  if (auto hit = parse_hit_condition(spec.hit_condition, &error)) {
    b.hit = *hit;
    resolve(b);
  } else {
    b.malformed = true;
    b.state.message = error;
  }
  if (!b.state.verified && b.state.line == 0) b.state.line = spec.line;
  return b;
}

std::vector<BreakpointState> Debugger::set_line_breakpoints(
    const std::string& file, const std::vector<BreakpointSpec>& specs) {
  std::erase_if(breakpoints_,
                [&](const Armed& b) { return b.spec.function.empty() && b.file == file; });
  for (const BreakpointSpec& spec : specs) breakpoints_.push_back(make_breakpoint(file, spec));
  arm();
  std::vector<BreakpointState> out;
  for (size_t i = breakpoints_.size() - specs.size(); i < breakpoints_.size(); ++i)
    out.push_back(breakpoints_[i].state);
  return out;
}

std::vector<BreakpointState> Debugger::set_function_breakpoints(
    const std::vector<BreakpointSpec>& specs) {
  std::erase_if(breakpoints_, [](const Armed& b) { return !b.spec.function.empty(); });
  for (const BreakpointSpec& spec : specs) breakpoints_.push_back(make_breakpoint({}, spec));
  arm();
  return states_of(true);
}

void Debugger::arm() {
  dialect::LoadedProgram* p = program();
  if (p == nullptr) {
    armed_for_ = nullptr;
    armed_pcs_.clear();
    return;
  }
  std::set<uint32_t> wanted;
  if (p != armed_for_) {
    // Another program (or the first): the breakpoints find their places in it afresh.
    armed_pcs_.clear();
    for (Armed& b : breakpoints_)
      if (!b.malformed) resolve(b);
    armed_for_ = p;
    seen_error_.assign(p->machine().thread_count(), 0);
  }
  for (const Armed& b : breakpoints_)
    if (b.pc) wanted.insert(*b.pc);
  vm::Machine& m = p->machine();
  for (uint32_t pc : armed_pcs_)
    if (!wanted.contains(pc)) m.clear_breakpoint(pc);
  armed_pcs_.clear();
  for (uint32_t pc : wanted)
    if (m.set_breakpoint(pc)) armed_pcs_.insert(pc);
  // The machine's table is full: what did not fit is said to be unverified, not kept quiet.
  for (Armed& b : breakpoints_) {
    if (!b.pc || armed_pcs_.contains(*b.pc)) continue;
    b.pc.reset();
    b.state.verified = false;
    b.state.message = "the program's breakpoint table is full";
  }
}

// --- execution ---

void Debugger::stop(StopReason reason, uint32_t thread, std::string description,
                    std::vector<uint32_t> ids) {
  state_ = RunState::Stopped;
  stop_ = Stop{reason, thread, std::move(description), std::move(ids)};
  stepping_.reset();
  // All-stop: every other thread halts where it stands until the program goes on.
  if (dialect::LoadedProgram* p = program()) {
    vm::Machine& m = p->machine();
    for (const dialect::ThreadInfo& t : drive_.firmware().threads()) {
      const vm::ThreadStatus s = m.status(t.thread);
      if (s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting) {
        m.halt(t.thread);
        halted_.push_back(t.thread);
      }
    }
  }
}

void Debugger::stop_at_entry() {
  stop(StopReason::Entry, threads().empty() ? 0 : threads().front().thread);
}

void Debugger::pause() {
  if (state_ != RunState::Running) return;
  const auto ts = threads();
  stop(StopReason::Pause, ts.empty() ? 0 : ts.front().thread);
}

void Debugger::start_running(std::optional<uint32_t> only_thread) {
  const bool was_stopped = state_ == RunState::Stopped;
  state_ = RunState::Running;
  dialect::LoadedProgram* p = program();
  if (p == nullptr) return;
  vm::Machine& m = p->machine();
  // A thread at a breakpoint's trap steps over it in the VM; one halted elsewhere (a step's end,
  // a pause) is told here.
  standing_.reset();
  if (was_stopped && m.status(stop_.thread) == vm::ThreadStatus::Halted)
    standing_ = Standing{stop_.thread, m.pc(stop_.thread)};
  std::vector<uint32_t> still_halted;
  for (uint32_t t : halted_) {
    if (only_thread && t != *only_thread)
      still_halted.push_back(t);
    else
      m.resume(t);
  }
  halted_ = std::move(still_halted);
  for (const dialect::ThreadInfo& t : drive_.firmware().threads()) {
    if (only_thread && t.thread != *only_thread) continue;
    if (m.status(t.thread) == vm::ThreadStatus::AtBreakpoint) m.resume(t.thread);
  }
}

bool Debugger::resumed_elsewhere() {
  dialect::LoadedProgram* p = program();
  if (state_ != RunState::Stopped || p == nullptr) return false;
  for (const dialect::ThreadInfo& t : drive_.firmware().threads()) {
    const vm::ThreadStatus s = p->machine().status(t.thread);
    if (s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting) {
      resume();
      return true;
    }
  }
  return false;
}

void Debugger::resume() {
  stepping_.reset();
  start_running(std::nullopt);
}

// A step runs its thread itself, an instruction at a time, so that it stops at the first
// instruction of a line however the firmware's slices fall; at each line end (and each wait)
// one firmware cycle passes with the thread held, as the line would take in the schedule.
void Debugger::step(uint32_t thread, StepKind kind, bool single_thread) {
  dialect::LoadedProgram* p = program();
  if (p == nullptr) return resume();
  vm::Machine& m = p->machine();
  stepping_ = Stepping{thread, kind, call_depth(thread), m.pc(thread)};
  start_running(single_thread ? std::optional<uint32_t>(thread) : std::nullopt);
  if (m.status(thread) == vm::ThreadStatus::Halted) m.resume(thread);
}

RunState Debugger::run(uint64_t budget_ns) {
  if (state_ != RunState::Running) return state_;
  arm();
  uint64_t spent = 0;
  while (state_ == RunState::Running && spent < budget_ns) {
    const uint64_t left = budget_ns - spent;
    if (drive_.ns_to_next_cycle() > left) {
      drive_.advance_ns(left);  // the rest of the budget, short of the next cycle: nothing runs
      break;
    }
    spent += std::max<uint64_t>(stepping_ ? step_slice() : advance_one_cycle(), 1);
    if (!stepping_) after_cycle();
  }
  return state_;
}

uint64_t Debugger::step_slice() {
  vm::Machine& m = program()->machine();
  const uint32_t t = stepping_->thread;
  for (uint32_t i = 0; i < kStepInstructionsPerCycle; ++i) {
    drive_.firmware().debug_runs(t);
    const vm::SliceResult r = m.run_slice(t, vm::Budget{1, 1, 0});
    drive_.firmware().debug_runs(scheduling::kNoThread);
    if (r.end == vm::SliceEnd::BudgetSpent) {
      if (step_done(t)) {
        stop(StopReason::Step, t);
        return 0;
      }
      continue;
    }
    if (r.end == vm::SliceEnd::Breakpoint) {
      if (at_trap(t)) return 0;
      continue;
    }
    if (r.end == vm::SliceEnd::Error || r.end == vm::SliceEnd::Finished ||
        r.end == vm::SliceEnd::NotRunning) {
      stepping_.reset();  // the thread has ended: what follows is the program's end or an exception
      after_cycle();
      return 0;
    }
    break;  // a line end, a wait, or halted: time passes
  }
  // One cycle with the stepping thread held: the others, the axes and the timers go on.
  const bool hold =
      m.status(t) == vm::ThreadStatus::Running || m.status(t) == vm::ThreadStatus::Waiting;
  if (hold) m.halt(t);
  const uint64_t ns = advance_one_cycle();
  if (hold) m.resume(t);
  after_cycle();
  if (state_ == RunState::Running && stepping_ && step_done(t)) stop(StopReason::Step, t);
  return ns;
}

uint64_t Debugger::advance_one_cycle() {
  const uint64_t ns = drive_.ns_to_next_cycle();
  drive_.advance_ns(ns);
  return ns;
}

void Debugger::clear_breakpoints() {
  breakpoints_.clear();
  arm();
}

std::vector<std::string> Debugger::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

// After each firmware cycle: a thread at a trap, a new run-time error, a finished step, the end.
void Debugger::after_cycle() {
  arm();  // the cycle may have loaded another program
  dialect::LoadedProgram* p = program();
  if (p == nullptr) {
    if (!drive_.program_running()) state_ = RunState::Ended;
    return;
  }
  vm::Machine& m = p->machine();
  if (standing_ && m.pc(standing_->thread) != standing_->pc) standing_.reset();  // it has left
  bool alive = false;
  for (const dialect::ThreadInfo& t : drive_.firmware().threads()) {
    const vm::ThreadStatus s = m.status(t.thread);
    if (s == vm::ThreadStatus::AtBreakpoint && at_trap(t.thread)) return;
    if (t.thread < seen_error_.size()) {
      if (s != vm::ThreadStatus::Error) {
        seen_error_[t.thread] = 0;
      } else if (!seen_error_[t.thread]) {
        seen_error_[t.thread] = 1;
        if (break_on_error_) {
          return stop(StopReason::Exception, t.thread, vm::run_error_text(m.last_error(t.thread)));
        }
      }
    }
    if (s != vm::ThreadStatus::Idle && s != vm::ThreadStatus::Error) alive = true;
  }
  if (!alive) state_ = RunState::Ended;
}

bool Debugger::step_done(uint32_t thread) const {
  const vm::Machine& m = program()->machine();
  const vm::ThreadStatus s = m.status(thread);
  if (s != vm::ThreadStatus::Running && s != vm::ThreadStatus::AtBreakpoint) return false;
  const uint32_t pc = m.pc(thread);
  if (m.frame_count(thread) == 0 || !is_line_start(program()->image(), pc)) return false;
  const uint32_t depth = call_depth(thread);
  if (depth == stepping_->depth && pc == stepping_->pc) return false;
  switch (stepping_->kind) {
    case StepKind::In:
      return true;
    case StepKind::Over:
      return depth <= stepping_->depth;
    case StepKind::Out:
      return depth < stepping_->depth;
  }
  return false;
}

// The dialect's own count where it builds frames itself (PDL), else the VM's.
uint32_t Debugger::call_depth(uint32_t thread) const {
  if (const auto d = drive_.firmware().debug_call_depth(thread)) return *d;
  return program()->machine().frame_count(thread);
}

bool Debugger::at_trap(uint32_t thread) {
  vm::Machine& m = program()->machine();
  const uint32_t pc = m.pc(thread);
  if (standing_ && standing_->thread == thread && standing_->pc == pc) {
    standing_.reset();  // leaving the place it stood on
    m.resume(thread);
    return false;
  }
  std::vector<uint32_t> hit;
  bool is_function = false;
  for (Armed& b : breakpoints_) {
    if (!b.pc || *b.pc != pc) continue;
    if (!b.spec.condition.empty()) {
      const dialect::Evaluation e = evaluate(thread, 0, b.spec.condition);
      if (!e.ok) {
        // A condition that cannot be evaluated stops, saying why, rather than passing silently.
        stop(StopReason::Breakpoint, thread,
             "the condition '" + b.spec.condition + "' failed: " + e.error, {b.id});
        return true;
      }
      if (!e.is_true) continue;
    }
    if (!b.hit.met(++b.hits)) continue;
    if (!b.spec.log_message.empty()) {
      messages_.push_back(interpolate(thread, b.spec.log_message));
      continue;
    }
    hit.push_back(b.id);
    is_function = is_function || !b.spec.function.empty();
  }
  if (!hit.empty()) {
    stop(is_function ? StopReason::FunctionBreakpoint : StopReason::Breakpoint, thread, {},
         std::move(hit));
    return true;
  }
  if (stepping_ && stepping_->thread == thread && step_done(thread)) {
    stop(StopReason::Step, thread);
    return true;
  }
  // Nothing stops here: the thread goes on in the next cycle.
  m.resume(thread);
  return false;
}

// "x is {x}": each {expression} replaced by its value in the dialect.
std::string Debugger::interpolate(uint32_t thread, const std::string& message) {
  std::string out;
  size_t i = 0;
  while (i < message.size()) {
    const size_t open = message.find('{', i);
    const size_t close = open == std::string::npos ? std::string::npos : message.find('}', open);
    if (close == std::string::npos) {
      out += message.substr(i);
      break;
    }
    out += message.substr(i, open - i);
    const dialect::Evaluation e = evaluate(thread, 0, message.substr(open + 1, close - open - 1));
    out += e.ok ? e.value : "<" + e.error + ">";
    i = close + 1;
  }
  return out;
}

}  // namespace uprog::debug
