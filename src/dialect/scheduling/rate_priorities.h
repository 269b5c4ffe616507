// Round-robin with per-thread rate priorities: each cycle every due thread executes one line,
// in thread order; priority k makes a thread due every k-th cycle from its start; held threads
// wait until released. Akribis's schedule (threads 1..8, an event routine holds 2..8).
#pragma once
#include <bit>
#include <cstdint>

#include "dialect/scheduling/line_step.h"
#include "dialect/scheduling/report.h"
#include "vm/machine.h"

namespace uprog::scheduling {

constexpr uint32_t kLowestRate = 1000;  // the largest priority: due every 1000th cycle

struct RatePrioritiesConfig {
  // The threads scheduled are first_thread .. first_thread + thread_count - 1; the threads
  // before them (the host line's) are not.
  uint32_t first_thread = 1;
  uint32_t thread_count = 8;
  uint64_t back_jump_cap = 1'000'000;  // a line that never ends stops after this many jumps back
};

// A thread in a wait (timed or a condition) spends its turns: it is due, and runs nothing
// until the wait is over. Past its last line a thread ends, in the cycle of that line.
class RatePriorities {
 public:
  explicit RatePriorities(RatePrioritiesConfig config = {});

  // One cycle: every due thread that is running or waiting and not held executes one line.
  Report cycle(vm::Machine& machine);
  uint64_t cycles() const { return cycle_; }

  // Tells the policy that `thread` (re)started: it is first due in the next cycle, then every
  // k-th. Call it with Machine::start; a thread never started is due on cycles k, 2k, ...
  void started(uint32_t thread);

  // 1 (every cycle, the default) .. kLowestRate; false, and no change, outside that range or
  // for a thread the policy does not schedule. The count stays anchored at the thread's start.
  bool set_priority(uint32_t thread, uint32_t priority);
  uint32_t priority(uint32_t thread) const;

  // A held thread is not due until released; its cycles keep counting from its start.
  void hold(uint32_t thread);
  void release(uint32_t thread);
  void release_all() { held_ = 0; }
  bool held(uint32_t thread) const { return covers(thread) && ((held_ >> thread) & 1u); }

  // The thread whose line runs now (inside cycle(), for the host's callbacks), else kNoThread.
  uint32_t running() const { return round_ != nullptr ? round_->at : running_; }
  bool covers(uint32_t thread) const {
    return thread >= config_.first_thread && thread - config_.first_thread < config_.thread_count;
  }

  // Priorities back to 1, nothing held, the cycle count at 0 (a reset of all programs).
  void reset();

 private:
  // The threads from `thread` on that take a turn now, one bit each (inline below).
  uint32_t ready_from(const vm::Machine& machine, uint32_t thread) const;
  // Returns the last thread the round ran or looked at. `turns`: one bit each.
  uint32_t run_round(vm::Machine& machine, uint32_t turns, Report& report);
  void take_turn(vm::Machine& machine, uint32_t thread, Report& report);  // one line, alone

  RatePrioritiesConfig config_;
  uint64_t cycle_ = 0;  // the cycle running now, or the last one run; the first is 1
  uint64_t start_cycle_[kMaxThreads] = {};
  uint32_t priority_[kMaxThreads] = {};
  uint32_t held_ = 0;
  uint32_t covered_ = 0;      // the threads scheduled, one bit each
  uint32_t slow_ = 0;         // those whose priority is not 1
  uint32_t started_now_ = 0;  // started in this cycle: first due in the next
  uint32_t running_ = kNoThread;
  const vm::Round* round_ = nullptr;  // inside run_round: the round, whose thread runs now
};

inline uint32_t RatePriorities::ready_from(const vm::Machine& machine, uint32_t thread) const {
  const uint32_t active =
      machine.threads_in(vm::ThreadStatus::Running) | machine.threads_in(vm::ThreadStatus::Waiting);
  uint32_t ready = active & covered_ & ~held_ & ~started_now_ & (~0u << thread);
  // A thread of priority k is due every k-th cycle from its start; most are due every cycle.
  for (uint32_t slow = ready & slow_; slow != 0; slow &= slow - 1) {
    const auto t = static_cast<uint32_t>(std::countr_zero(slow));
    if ((cycle_ - start_cycle_[t]) % priority_[t] != 0) ready &= ~(1u << t);
  }
  return ready;
}

// The running threads due from `thread` on, up to the first waiting one, take their lines in
// one round; a line that calls the host ends it, and the threads after are looked at again.
inline Report RatePriorities::cycle(vm::Machine& machine) {
  Report report;
  ++cycle_;
  started_now_ = 0;
  uint32_t thread = config_.first_thread;
  while (thread < kMaxThreads) {
    const uint32_t ready = ready_from(machine, thread);
    if (ready == 0) break;
    const uint32_t waiting = ready & machine.threads_in(vm::ThreadStatus::Waiting);
    const uint32_t before_waiting = waiting != 0 ? (waiting & -waiting) - 1 : ~0u;
    if (const uint32_t round = ready & ~waiting & before_waiting; round != 0) {
      thread = run_round(machine, round, report) + 1;
    } else {
      thread = static_cast<uint32_t>(std::countr_zero(waiting));
      take_turn(machine, thread, report);
      ++thread;
    }
  }
  return report;
}

inline uint32_t RatePriorities::run_round(vm::Machine& machine, uint32_t turns, Report& report) {
  vm::Round round{turns};
  round_ = &round;
  const vm::SliceResult last = machine.run_round(round, vm::Budget{0, 1, config_.back_jump_cap});
  round_ = nullptr;
  const uint32_t thread = round.at;
  report.mark_ran_all(turns & ((1u << thread) - 1));  // the turns before round.at ran
  if (last.end == vm::SliceEnd::NotRunning) {
    take_turn(machine, thread, report);  // it cannot start in a round
  } else {
    running_ = thread;
    report_step(report, thread, finish_step(machine, thread, last, true, config_.back_jump_cap));
    running_ = kNoThread;
  }
  return thread;
}

}  // namespace uprog::scheduling
