// Round-robin, one command per phase: each phase one line of one task runs, turns going 1, 2,
// 3, 1, ... over the active tasks, with a lock that gives one task every phase. PDL's schedule.
#pragma once
#include <cstdint>

#include "dialect/scheduling/report.h"
#include "vm/machine.h"

namespace uprog::scheduling {

struct PhaseRoundRobinConfig {
  // The tasks that take turns are threads first_thread .. first_thread + task_count - 1; the
  // threads before them (the system's task 0, the host line) get no turn.
  uint32_t first_thread = 1;
  uint32_t task_count = 3;
  uint64_t back_jump_cap = 1'000'000;  // a line that never ends stops after this many jumps back
};

struct PhaseResult {
  // The task that had this phase's turn: it ran a command or spent the turn in a condition
  // wait. kNoThread when no task was active (all idle, sleeping, halted) or the holder of the
  // lock sleeps.
  uint32_t turn = kNoThread;
  Report report;
};

// A task is active when it is running or in a condition wait (a YIELD: `till`, `wait n`);
// a timed wait (WAIT: `sleep n`) takes it out of turn until its time. The turn in which a
// sleeping task wakes runs the rest of the sleep's line and its next command: the sleep's
// phase was spent when it began.
class PhaseRoundRobin {
 public:
  explicit PhaseRoundRobin(PhaseRoundRobinConfig config = {});

  // One phase: the holder of the lock, or else the next active task after the last one that
  // had a turn, runs one command.
  PhaseResult phase(vm::Machine& machine);

  // From the next phase only `thread` runs, every phase, until it unlocks or ends. A lock while
  // one is held, and an unlock by a task that does not hold it, do nothing.
  void lock(uint32_t thread);
  void unlock(uint32_t thread);
  uint32_t lock_holder() const { return holder_; }

  // The task whose command runs now (inside phase(), for the host's callbacks), else kNoThread.
  uint32_t running() const { return running_; }
  bool is_task(uint32_t thread) const {
    return thread >= config_.first_thread && thread - config_.first_thread < config_.task_count;
  }

  // Forgets the lock and the turn order (a drive reset): the next turn is the first task's.
  void reset();

 private:
  // Gives `thread` the phase; false when it was not active (idle, halted, asleep).
  bool take_turn(vm::Machine& machine, uint32_t thread, PhaseResult& out);

  PhaseRoundRobinConfig config_;
  uint32_t last_turn_ = kNoThread;
  uint32_t holder_ = kNoThread;
  uint32_t running_ = kNoThread;
};

}  // namespace uprog::scheduling
