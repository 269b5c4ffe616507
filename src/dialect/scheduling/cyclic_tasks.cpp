// Cyclic tasks: ticks run the due real-time tasks in period order within their line budgets;
// the background slice runs the init task, then the restarting background loop, on what is left.
#include "dialect/scheduling/cyclic_tasks.h"

#include "bytecode/opcodes.h"
#include "dialect/scheduling/line_step.h"

namespace uprog::scheduling {

namespace {

constexpr uint64_t kSecondNs = 1'000'000'000;

// A line is counted when it ends, or when the run ends inside it; a line that stops at a wait,
// a yield or a breakpoint is counted by the step that finishes it. A step cut by the back-jump
// cap counts its last line too, so that a line that never ends still spends the budget; a
// program that ends without a line (an empty one) costs one, as its bare end's step.
uint64_t lines_of(const LineStep& s) {
  switch (s.end) {
    case vm::SliceEnd::Error:
    case vm::SliceEnd::BudgetSpent:
      return s.lines + 1;
    case vm::SliceEnd::Finished:
      return s.lines == 0 ? 1 : s.lines;
    default:
      return s.lines;
  }
}

bool can_step(vm::ThreadStatus status) {
  return status == vm::ThreadStatus::Running || status == vm::ThreadStatus::Waiting;
}

}  // namespace

bool CyclicTasks::add_task(uint32_t thread, uint32_t routine, uint64_t period_ns) {
  const uint64_t tick_ns = config_.tick_ns;
  if (started_ || task_count_ == kMaxTasks || tick_ns == 0 || config_.line_ns == 0) return false;
  if (period_ns == 0 || period_ns % tick_ns != 0) return false;
  uint32_t at = task_count_;
  while (at > 0 && tasks_[at - 1].stats.period_ns > period_ns) {
    tasks_[at] = tasks_[at - 1];
    --at;
  }
  Task& task = tasks_[at];
  task = Task{};
  task.routine = routine;
  task.period_ticks = period_ns / tick_ns;
  task.stats.thread = thread;
  task.stats.period_ns = period_ns;
  task.stats.budget_lines = period_ns / config_.line_ns;
  ++task_count_;
  return true;
}

bool CyclicTasks::set_init(uint32_t thread, uint32_t routine) {
  if (started_) return false;
  init_ = {thread, routine};
  return true;
}

bool CyclicTasks::set_background(uint32_t thread, uint32_t routine, uint32_t pass_local) {
  if (started_) return false;
  main_ = {thread, routine, pass_local};
  return true;
}

void CyclicTasks::clear() {
  if (started_) return;
  task_count_ = 0;
  init_ = {};
  main_ = {};
}

void CyclicTasks::reset_statistics() {
  for (uint32_t i = 0; i < task_count_; ++i) {
    CyclicTaskStats& s = tasks_[i].stats;
    s.runs = s.last_run_lines = s.largest_run_lines = s.overruns = 0;
  }
  loops_this_second_ = loops_last_second_ = 0;
}

bool CyclicTasks::threads_valid(const vm::Machine& machine) const {
  const auto fits = [&](uint32_t thread) {
    return thread < machine.thread_count() && thread < kMaxThreads;
  };
  uint32_t used = 0;
  for (uint32_t i = 0; i < task_count_; ++i) {
    const uint32_t thread = tasks_[i].stats.thread;
    if (!fits(thread) || ((used >> thread) & 1u)) return false;
    used |= 1u << thread;
  }
  // The init and background programs may share a thread: one ends before the other starts.
  const auto free = [&](const Program& p) {
    return !p.set() || (fits(p.thread) && ((used >> p.thread) & 1u) == 0);
  };
  return free(init_) && free(main_);
}

// Each routine starts on its thread (exists, takes no inputs, its locals fit), so that a run's
// start later cannot fail.
bool CyclicTasks::routines_start(vm::Machine& machine) const {
  const auto starts = [&](uint32_t thread, uint32_t routine) {
    const bool ok = machine.start(thread, routine) == vm::RunError::None;
    machine.kill(thread);
    return ok;
  };
  for (uint32_t i = 0; i < task_count_; ++i) {
    if (!starts(tasks_[i].stats.thread, tasks_[i].routine)) return false;
  }
  if (init_.set() && !starts(init_.thread, init_.routine)) return false;
  return !main_.set() || starts(main_.thread, main_.routine);
}

bool CyclicTasks::start(vm::Machine& machine, uint64_t now_ns) {
  stop(machine);
  if (!machine.loaded() || !threads_valid(machine) || !routines_start(machine)) return false;
  started_ = true;
  held_ = 0;
  init_done_ = !init_.set();
  next_tick_ = 1;
  next_tick_ns_ = now_ns + config_.tick_ns;
  begin_real_time(1);
  accrued_ns_ = now_ns;
  accrued_remainder_ns_ = 0;
  credit_lines_ = 0;
  rt_lines_ = 0;
  second_end_ns_ = now_ns + kSecondNs;
  passes_at_second_ = 0;
  if (main_.set()) main_entry_ = machine.image().routines[main_.routine].entry;
  reset_statistics();
  for (uint32_t i = 0; i < task_count_; ++i) {
    tasks_[i].state = RunState::Ready;
    tasks_[i].run_lines = 0;
  }
  if (init_.set()) {
    machine.start(init_.thread, init_.routine);
  } else if (main_.set()) {
    machine.start(main_.thread, main_.routine);
  }
  return true;
}

void CyclicTasks::stop(vm::Machine& machine, uint32_t failed) {
  const auto kill = [&](uint32_t thread) {
    if (thread != failed) machine.kill(thread);
  };
  for (uint32_t i = 0; i < task_count_; ++i) kill(tasks_[i].stats.thread);
  if (init_.set()) kill(init_.thread);
  if (main_.set()) kill(main_.thread);
  started_ = false;
  held_ = 0;
}

Report CyclicTasks::run(vm::Machine& machine, uint64_t now_ns) {
  Report report;
  if (!started_) return report;
  while (next_tick_ns_ <= now_ns) {
    const uint64_t tick = next_tick_++;
    next_tick_ns_ += config_.tick_ns;
    if (init_done_ && tick >= first_rt_tick_ && run_tick(machine, tick, report) == Flow::EndCall)
      return report;
  }
  run_background(machine, now_ns, report);
  return report;
}

// Inline: every run of every task goes through it (the S300's PLC62 16 000 times a second).
[[gnu::always_inline]] inline CyclicTasks::Step CyclicTasks::step(vm::Machine& machine,
                                                                  uint32_t thread, uint64_t lines,
                                                                  Report& report) {
  running_ = thread;
  charged_ = 0;
  const LineStep s = step_lines(machine, thread, lines, config_.back_jump_cap);
  running_ = kNoThread;
  if (s.ran) report.mark_ran(thread);
  if (s.end == vm::SliceEnd::Error) report.add(thread, ThreadEvent::Error);
  if (s.end == vm::SliceEnd::Breakpoint) report.add(thread, ThreadEvent::Breakpoint);
  return {lines_of(s) + charged_, s.end, charged_ != 0};
}

// Up to `lines` lines in one slice. A host call that charged lines and ended the slice (a costly
// one) has its line finished in the same step, so that the budget is looked at only where a line
// ends; the program's own yield pauses the run as a wait does. Inline, the rare part apart: every
// run of every task goes through it.
inline CyclicTasks::Step CyclicTasks::slice(vm::Machine& machine, uint32_t thread, uint64_t lines,
                                            Report& report) {
  const Step s = step(machine, thread, lines, report);
  if (s.end == vm::SliceEnd::Yielded && s.charged) [[unlikely]]
    return finish_charged_line(machine, thread, s, report);
  return s;
}

[[gnu::noinline]] CyclicTasks::Step CyclicTasks::finish_charged_line(vm::Machine& machine,
                                                                     uint32_t thread, Step s,
                                                                     Report& report) {
  while (s.end == vm::SliceEnd::Yielded && s.charged) {
    const Step rest = step(machine, thread, 1, report);
    s = {s.cost + rest.cost, rest.end, rest.charged};
  }
  return s;
}

// Inline: every run begins and ends through them.
inline bool CyclicTasks::begin_run(vm::Machine& machine, Task& task) {
  // start() proved that it starts (false only when the machine changed under the schedule).
  if (machine.restart(task.stats.thread, task.routine) != vm::RunError::None) return false;
  task.state = RunState::InRun;
  task.run_lines = 0;
  return true;
}

// Whether a run under way may take its next slice: not when its thread was killed from outside
// (the next period starts afresh), nor while it is halted or at a breakpoint (until resumed).
inline bool CyclicTasks::goes_on(const vm::Machine& machine, Task& task) {
  const vm::ThreadStatus status = machine.status(task.stats.thread);
  if (status == vm::ThreadStatus::Idle || status == vm::ThreadStatus::Error) {
    task.state = RunState::Ready;
    return false;
  }
  return can_step(status);
}

inline void CyclicTasks::end_run(Task& task) {
  task.state = RunState::Ready;
  ++task.stats.runs;
  task.stats.last_run_lines = task.run_lines;
  if (task.run_lines > task.stats.largest_run_lines) task.stats.largest_run_lines = task.run_lines;
}

// Inline into run(), as run_task() into it: the whole schedule of a tick in one function.
[[gnu::always_inline]] inline CyclicTasks::Flow CyclicTasks::run_tick(vm::Machine& machine,
                                                                      uint64_t tick,
                                                                      Report& report) {
  for (uint32_t i = 0; i < task_count_; ++i) {
    Task& task = tasks_[i];
    // A tick whose call ended early skipped the tasks after the one that ended it: they wait
    // for their next period, as (tick - first_rt_tick_) % period_ticks says.
    while (task.due_tick < tick) task.due_tick += task.period_ticks;
    if (task.due_tick != tick) continue;
    task.due_tick += task.period_ticks;
    if (run_task(machine, task, report) == Flow::EndCall) return Flow::EndCall;
  }
  return Flow::Continue;
}

[[gnu::always_inline]] inline CyclicTasks::Flow CyclicTasks::run_task(vm::Machine& machine,
                                                                      Task& task, Report& report) {
  const uint32_t thread = task.stats.thread;
  if (task.state == RunState::Stopped) return Flow::Continue;
  if (task.state == RunState::Ready) {
    // Held between runs, else a run begins: its thread runs (no status to look at).
    if (held_bit(thread) || !begin_run(machine, task)) return Flow::Continue;
  } else if (!goes_on(machine, task)) {
    return Flow::Continue;
  }
  for (;;) {
    if (task.run_lines >= task.stats.budget_lines) return overrun(machine, task, report);
    const Step s = slice(machine, thread, task.stats.budget_lines - task.run_lines, report);
    task.run_lines += s.cost;
    rt_lines_ += s.cost;
    switch (s.end) {
      case vm::SliceEnd::LineEnd:
      case vm::SliceEnd::BudgetSpent:
        // The run goes on, unless a host call stopped its thread; then its budget is looked at.
        if (!goes_on(machine, task)) return Flow::Continue;
        continue;
      case vm::SliceEnd::Finished:
        if (task.run_lines > task.stats.budget_lines) return overrun(machine, task, report);
        end_run(task);
        return Flow::Continue;
      case vm::SliceEnd::Error:
        task.state = RunState::Stopped;
        return Flow::EndCall;
      default:
        return Flow::Continue;  // a wait, a yield, a breakpoint: the run pauses
    }
  }
}

CyclicTasks::Flow CyclicTasks::overrun(vm::Machine& machine, Task& task, Report& report) {
  machine.halt(task.stats.thread);  // where it stands, for the debugger
  task.state = RunState::Stopped;
  ++task.stats.overruns;
  if (task.run_lines > task.stats.largest_run_lines) task.stats.largest_run_lines = task.run_lines;
  report.add(task.stats.thread, ThreadEvent::Overrun);
  return Flow::EndCall;
}

void CyclicTasks::accrue(uint64_t now_ns) {
  if (now_ns > accrued_ns_) {
    const uint64_t time_ns = accrued_remainder_ns_ + (now_ns - accrued_ns_);
    credit_lines_ += static_cast<int64_t>(time_ns / config_.line_ns);
    accrued_remainder_ns_ = time_ns % config_.line_ns;
    accrued_ns_ = now_ns;
  }
  credit_lines_ -= static_cast<int64_t>(rt_lines_);
  rt_lines_ = 0;
}

void CyclicTasks::run_background(vm::Machine& machine, uint64_t now_ns, Report& report) {
  if (init_done_ && !main_.set()) {
    // No background to give lines to: the CPU idles after the real-time tasks, every cycle
    // (the credit would be dropped below; counting it cost a division a cycle).
    rt_lines_ = 0;
    credit_lines_ = 0;
    accrued_ns_ = now_ns;
    accrued_remainder_ns_ = 0;
    latch_seconds(machine, now_ns);
    return;
  }
  accrue(now_ns);
  if (!init_done_) {
    run_init(machine, report);
  } else {
    run_main(machine, report);
  }
  if (credit_lines_ > 0) credit_lines_ = 0;  // the CPU idled: unused lines are lost
  latch_seconds(machine, now_ns);
}

void CyclicTasks::run_init(vm::Machine& machine, Report& report) {
  while (credit_lines_ > 0 && can_step(machine.status(init_.thread))) {
    const Step s = slice(machine, init_.thread, static_cast<uint64_t>(credit_lines_), report);
    credit_lines_ -= static_cast<int64_t>(s.cost);
    if (s.end != vm::SliceEnd::LineEnd && s.end != vm::SliceEnd::BudgetSpent) break;
  }
  // Out of lines, waiting, halted or failed: not done yet. Idle: it finished (or was killed).
  if (machine.status(init_.thread) == vm::ThreadStatus::Idle) end_init(machine, report);
}

void CyclicTasks::end_init(vm::Machine& machine, Report& report) {
  report.add(init_.thread, ThreadEvent::Finished);
  init_done_ = true;
  // The real-time tasks and the background begin together; the rest of this slice is lost.
  begin_real_time(next_tick_);
  if (main_.set()) machine.start(main_.thread, main_.routine);
}

void CyclicTasks::run_main(vm::Machine& machine, Report& report) {
  if (!main_.set()) return;
  // A thread that cannot run (halted, stopped, killed) ends the slice at its first step.
  while (credit_lines_ > 0) {
    const Step s = slice(machine, main_.thread, static_cast<uint64_t>(credit_lines_), report);
    credit_lines_ -= static_cast<int64_t>(s.cost);
    switch (s.end) {
      case vm::SliceEnd::LineEnd:
      case vm::SliceEnd::BudgetSpent:
        break;
      case vm::SliceEnd::Finished:
        end_pass(machine);
        break;
      default:
        return;  // a wait, a yield, a breakpoint, an error, not running: the slice ends
    }
  }
}

// Every task is due at the first real-time tick, then every period after it.
void CyclicTasks::begin_real_time(uint64_t first_tick) {
  first_rt_tick_ = first_tick;
  for (uint32_t i = 0; i < task_count_; ++i) tasks_[i].due_tick = first_tick;
}

void CyclicTasks::end_pass(vm::Machine& machine) {
  ++loops_this_second_;
  machine.start(main_.thread, main_.routine);  // at its top again
}

// The looping background's passes finished: those begun, less the one under way (unless the
// thread stands at its top or at the jump back to it). Its counter wraps as a 32-bit int.
uint32_t CyclicTasks::main_passes_done(const vm::Machine& machine) const {
  const uint32_t thread = main_.thread;
  const uint32_t frames = machine.frame_count(thread);
  Value begun;
  if (frames == 0 || !machine.read_local(thread, frames - 1, main_.pass_local, begun))
    return passes_at_second_;  // not running: nothing more finished
  const uint32_t pc = machine.pc(thread);
  const bytecode::ImageView& image = machine.image();
  bool between = pc == main_entry_;
  if (!between && frames == 1 && pc < image.code.size()) {
    const uint32_t word = image.code[pc];
    between = bytecode::word_op(word) == bytecode::Op::JMP && bytecode::word_a(word) == main_entry_;
  }
  return static_cast<uint32_t>(begun.i) - (between ? 0u : 1u);
}

void CyclicTasks::latch_seconds(const vm::Machine& machine, uint64_t now_ns) {
  if (now_ns < second_end_ns_) return;
  if (init_done_ && main_.set() && main_.pass_local != kNoLocal) {
    const uint32_t done = main_passes_done(machine);
    loops_this_second_ += static_cast<uint32_t>(done - passes_at_second_);
    passes_at_second_ = done;
  }
  while (now_ns >= second_end_ns_) {
    loops_last_second_ = loops_this_second_;
    loops_this_second_ = 0;
    second_end_ns_ += kSecondNs;
  }
}

// --- the debug commands' holds and steps ---

uint32_t CyclicTasks::task_index(uint32_t thread) const {
  uint32_t i = 0;
  while (i < task_count_ && tasks_[i].stats.thread != thread) ++i;
  return i;
}

bool CyclicTasks::stopped(uint32_t thread) const {
  const uint32_t i = task_index(thread);
  return i < task_count_ && tasks_[i].state == RunState::Stopped;
}

void CyclicTasks::hold(vm::Machine& machine, uint32_t thread) {
  if (!started_ || thread >= kMaxThreads) return;
  held_ |= 1u << thread;
  if (can_step(machine.status(thread))) machine.halt(thread);
}

void CyclicTasks::release(vm::Machine& machine, uint32_t thread) {
  if (!started_ || thread >= kMaxThreads) return;
  held_ &= ~(1u << thread);
  const vm::ThreadStatus s = machine.status(thread);
  if (!stopped(thread) && (s == vm::ThreadStatus::Halted || s == vm::ThreadStatus::AtBreakpoint))
    machine.resume(thread);
}

bool CyclicTasks::held(const vm::Machine& machine, uint32_t thread) const {
  if (!started_ || thread >= kMaxThreads || stopped(thread)) return false;
  const vm::ThreadStatus s = machine.status(thread);
  return held_bit(thread) || s == vm::ThreadStatus::Halted || s == vm::ThreadStatus::AtBreakpoint;
}

bool CyclicTasks::step_held(vm::Machine& machine, uint32_t thread, Report& report) {
  if (!held(machine, thread)) return false;
  const uint32_t index = task_index(thread);
  Task* task = index < task_count_ ? &tasks_[index] : nullptr;
  if (task != nullptr && !init_done_) return false;
  const vm::ThreadStatus before = machine.status(thread);
  if (before == vm::ThreadStatus::Halted || before == vm::ThreadStatus::AtBreakpoint) {
    machine.resume(thread);
  } else if (task != nullptr && task->state == RunState::Ready) {
    begin_run(machine, *task);
  }
  if (!can_step(machine.status(thread))) return false;  // the init task's thread after its end
  held_ |= 1u << thread;
  const Step s = slice(machine, thread, 1, report);
  if (s.end == vm::SliceEnd::Finished) {
    if (task != nullptr) {
      end_run(*task);
    } else if (!init_done_) {
      end_init(machine, report);
    } else {
      end_pass(machine);
    }
  } else if (s.end == vm::SliceEnd::Error && task != nullptr) {
    task->state = RunState::Stopped;
  }
  if (can_step(machine.status(thread))) machine.halt(thread);
  return true;
}

}  // namespace uprog::scheduling
