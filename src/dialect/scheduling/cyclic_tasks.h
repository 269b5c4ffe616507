// Cyclic tasks with their own periods: each tick the due real-time tasks run to completion,
// fastest first, each within a line budget (one line more is an overrun); an init task runs
// alone first; a background loop restarts at its top and gets the lines the others left.
// The S300's PLC programs (PLC62 … PLC16, PLCINIT, PLCMAIN).
#pragma once
#include <cstdint>

#include "dialect/scheduling/report.h"
#include "vm/machine.h"

namespace uprog::scheduling {

struct CyclicTasksConfig {
  uint64_t tick_ns = 62'500;  // the real-time tasks' periods are whole numbers of ticks
  uint64_t line_ns = 160;     // what a line costs: a run of period P may execute P / line_ns
  uint64_t back_jump_cap = 1'000'000;  // a line that never ends stops after this many jumps back
};

// What TASK reports of a real-time task.
struct CyclicTaskStats {
  uint32_t thread = kNoThread;
  uint64_t period_ns = 0;
  uint64_t budget_lines = 0;  // lines one run may execute: period_ns / line_ns
  uint64_t runs = 0;          // runs finished
  uint64_t last_run_lines = 0;
  uint64_t largest_run_lines = 0;  // an overrun counts with the lines it used (100 % or more)
  uint64_t overruns = 0;
  // The largest run in whole percent of the budget, truncated.
  uint64_t largest_run_percent() const {
    return budget_lines == 0 ? 0 : largest_run_lines * 100 / budget_lines;
  }
};

// Lines are counted as they end (line_step.h), the end of a run ending its last one; a host call
// may charge more (charge()) and then end the slice (vm::kCommandEndSlice), which finishes its
// line before the budget is looked at again. Each run goes in one machine slice of the lines it
// may still use: a real-time run its budget, the background its credit (the machine counts the
// line ends), so a line costs the same as when stepped one by one. A run that waits pauses until
// the task is next due and goes on counting the same run; a halted task or one at a breakpoint
// is skipped until resumed.
// An overrun or an uncaught error ends the call at once and stops that task until start(): the
// firmware decides what else stops. A real-time run's end and the background's restart are
// the schedule itself, not events: the report says Finished only for the init task.
class CyclicTasks {
 public:
  static constexpr uint32_t kMaxTasks = 8;

  explicit CyclicTasks(CyclicTasksConfig config = {}) : config_(config) {}

  // The programs, set while stopped. add_task is false when kMaxTasks are set or the period is
  // not a positive whole number of ticks; tasks run fastest first, in the order added when
  // their periods are equal.
  bool add_task(uint32_t thread, uint32_t routine, uint64_t period_ns);
  // The init and background programs may share a thread; false while started. A background
  // routine that loops by itself names the local it counts its passes in (one added at its top,
  // the routine's entry, which nothing else jumps to); without one it is started again each time
  // it finishes.
  static constexpr uint32_t kNoLocal = UINT32_MAX;
  bool set_init(uint32_t thread, uint32_t routine);
  bool set_background(uint32_t thread, uint32_t routine, uint32_t pass_local = kNoLocal);
  void clear();  // no tasks, no init, no background (while started: nothing)

  // Starts at `now_ns`: the init task alone first (when there is one), in background slices;
  // once it has finished, the real-time tasks from the next tick (all due then) and the
  // background loop. False, with nothing started, when a thread is out of range or used
  // twice, or the machine refuses to start a routine.
  bool start(vm::Machine& machine, uint64_t now_ns);
  // Kills every thread of the programs but `failed` (one stopped by its error, kept for the
  // debugger to show where); nothing runs until start().
  void stop(vm::Machine& machine, uint32_t failed = kNoThread);
  bool started() const { return started_; }
  bool init_done() const { return init_done_; }

  // Runs the ticks that have come by `now_ns` (a tick at start + k·tick_ns, k ≥ 1), then one
  // background slice with the lines accrued since the last one, less those the real-time tasks
  // used (a debt carries over; lines the background cannot use are lost).
  Report run(vm::Machine& machine, uint64_t now_ns);

  // Adds `lines` to what the run in progress has used (a costly host call inside it).
  void charge(uint64_t lines) { charged_ += lines; }
  // The thread whose line runs now (inside run(), for the host's callbacks), else kNoThread.
  uint32_t running() const { return running_; }

  uint32_t task_count() const { return task_count_; }
  // Task i in the order they run (fastest first); past task_count(), an empty record.
  const CyclicTaskStats& stats(uint32_t i) const {
    return i < task_count_ ? tasks_[i].stats : kNoStats;
  }
  // Background loops finished in the last whole virtual second since start; 0 while stopped.
  uint64_t background_loops_last_second() const { return started_ ? loops_last_second_ : 0; }
  void reset_statistics();

  // The drive's debug commands (docs/dialects/st.md, "Debug commands"). A held program stops
  // where it stands, and a held real-time task begins no run: its due ticks pass without it.
  // release() lets it go on (a run held in the middle at its next due tick); start() and stop()
  // release every thread. A thread the debugger halted or stopped at a breakpoint counts as held.
  void hold(vm::Machine& machine, uint32_t thread);
  void release(vm::Machine& machine, uint32_t thread);
  bool held(const vm::Machine& machine, uint32_t thread) const;
  // Runs a held program's next line and holds it again: a real-time task between runs begins
  // its next run, a run that ends counts, the background begins its next pass at its top, the
  // init task's end starts the others. The line costs no budget. False, with nothing run, when
  // the thread is not held or has no line to run (stopped; a real-time task before the init task
  // has ended; the init task after it).
  bool step_held(vm::Machine& machine, uint32_t thread, Report& report);
  // A real-time task that an overrun or an error stopped.
  bool stopped(uint32_t thread) const;

 private:
  enum class RunState : uint8_t { Ready, InRun, Stopped };
  struct Task {
    uint32_t routine = 0;
    uint64_t period_ticks = 0;
    uint64_t due_tick = 0;  // its next period's tick (counted, not divided: run_tick is hot)
    RunState state = RunState::Ready;
    uint64_t run_lines = 0;
    CyclicTaskStats stats;
  };
  struct Program {
    uint32_t thread = kNoThread;
    uint32_t routine = 0;
    uint32_t pass_local = kNoLocal;
    bool set() const { return thread != kNoThread; }
  };
  // How a run of steps ended: the caller goes on, or the call ends (overrun, error).
  enum class Flow : uint8_t { Continue, EndCall };
  // The count first: 16 bytes, returned in two registers.
  struct Step {
    uint64_t cost;  // lines: those it ended, plus the host's charges
    vm::SliceEnd end;
    bool charged;  // a host call charged lines (and may have ended the slice inside its line)
  };

  bool held_bit(uint32_t thread) const {
    return thread < kMaxThreads && ((held_ >> thread) & 1u) != 0;
  }
  uint32_t task_index(uint32_t thread) const;  // task_count_ when no real-time task runs on it
  bool begin_run(vm::Machine& machine, Task& task);  // false: its thread did not start
  bool goes_on(const vm::Machine& machine, Task& task);
  void end_run(Task& task);
  void end_init(vm::Machine& machine, Report& report);
  void begin_real_time(uint64_t first_tick);
  void end_pass(vm::Machine& machine);
  bool threads_valid(const vm::Machine& machine) const;
  bool routines_start(vm::Machine& machine) const;
  Step step(vm::Machine& machine, uint32_t thread, uint64_t lines, Report& report);
  Step slice(vm::Machine& machine, uint32_t thread, uint64_t lines, Report& report);
  Step finish_charged_line(vm::Machine& machine, uint32_t thread, Step s, Report& report);
  uint32_t main_passes_done(const vm::Machine& machine) const;
  Flow run_tick(vm::Machine& machine, uint64_t tick, Report& report);
  Flow run_task(vm::Machine& machine, Task& task, Report& report);
  Flow overrun(vm::Machine& machine, Task& task, Report& report);
  void run_background(vm::Machine& machine, uint64_t now_ns, Report& report);
  void run_init(vm::Machine& machine, Report& report);
  void run_main(vm::Machine& machine, Report& report);
  void accrue(uint64_t now_ns);
  void latch_seconds(const vm::Machine& machine, uint64_t now_ns);

  static constexpr CyclicTaskStats kNoStats{};

  CyclicTasksConfig config_;
  Task tasks_[kMaxTasks];
  uint32_t task_count_ = 0;
  Program init_;
  Program main_;

  bool started_ = false;
  bool init_done_ = false;
  uint64_t next_tick_ = 1;      // the tick run() does next; tick k comes at start + k·tick_ns
  uint64_t next_tick_ns_ = 0;   // when that tick comes (added up, not multiplied: run() is hot)
  uint64_t first_rt_tick_ = 0;  // the first tick after the init task: every task is due
  uint64_t accrued_ns_ = 0;     // time up to which the background's lines have been credited
  uint64_t accrued_remainder_ns_ = 0;  // time short of a whole line, credited later
  int64_t credit_lines_ = 0;  // the background's lines; below 0, a debt to the real-time tasks
  uint64_t rt_lines_ = 0;     // lines the real-time tasks used since the last background slice
  uint64_t charged_ = 0;
  uint32_t running_ = kNoThread;
  uint32_t held_ = 0;  // a bit per thread: held by hold()
  uint64_t second_end_ns_ = 0;
  uint64_t loops_this_second_ = 0;
  uint64_t loops_last_second_ = 0;
  uint32_t main_entry_ = 0;        // the looping background's top
  uint32_t passes_at_second_ = 0;  // its passes finished when the last second was latched
};

}  // namespace uprog::scheduling
