// Round-robin with per-thread rate priorities: each cycle every due thread executes one line,
// in thread order; priority k makes a thread due every k-th cycle from its start; held threads
// wait until released. Akribis's schedule (threads 1..8, an event routine holds 2..8).
#pragma once
#include <cstdint>

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
  uint32_t running() const { return round_ != nullptr ? round_->threads[round_->at] : running_; }
  bool covers(uint32_t thread) const {
    return thread >= config_.first_thread && thread - config_.first_thread < config_.thread_count;
  }

  // Priorities back to 1, nothing held, the cycle count at 0 (a reset of all programs).
  void reset();

 private:
  // Inline below: cycle() asks them of every thread, every cycle.
  bool due(uint32_t thread) const;
  // This cycle, with the status the machine gives it; `thread` is one this policy covers.
  bool takes_turn(vm::ThreadStatus status, uint32_t thread) const;
  // Returns the last thread the round ran or looked at. `gathered`: the turns, one bit each.
  uint32_t run_round(vm::Machine& machine, const uint32_t* turns, uint32_t count,
                     uint32_t gathered, Report& report);
  void take_turn(vm::Machine& machine, uint32_t thread, Report& report);  // one line, alone

  RatePrioritiesConfig config_;
  uint64_t cycle_ = 0;  // the cycle running now, or the last one run; the first is 1
  uint64_t start_cycle_[kMaxThreads] = {};
  uint32_t priority_[kMaxThreads] = {};
  uint32_t held_ = 0;
  uint32_t running_ = kNoThread;
  const vm::Round* round_ = nullptr;  // inside run_round: the round, whose thread runs now
};

inline bool RatePriorities::due(uint32_t thread) const {
  const uint64_t start = start_cycle_[thread];
  // Most threads run every cycle: no division for them.
  return cycle_ >= start && (priority_[thread] == 1 || (cycle_ - start) % priority_[thread] == 0);
}

inline bool RatePriorities::takes_turn(vm::ThreadStatus status, uint32_t thread) const {
  return (status == vm::ThreadStatus::Running || status == vm::ThreadStatus::Waiting) &&
         ((held_ >> thread) & 1u) == 0 && due(thread);
}

}  // namespace uprog::scheduling
