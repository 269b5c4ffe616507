// One command per phase over the active tasks, in task order, or only the lock's holder.
#include "dialect/scheduling/phase_round_robin.h"

#include "dialect/scheduling/line_step.h"

namespace uprog::scheduling {

namespace {

bool has_ended(vm::ThreadStatus status) {
  return status == vm::ThreadStatus::Idle || status == vm::ThreadStatus::Error;
}

}  // namespace

PhaseRoundRobin::PhaseRoundRobin(PhaseRoundRobinConfig config) : config_(config) {
  // A report names at most kMaxThreads threads.
  if (config_.first_thread >= kMaxThreads) config_.task_count = 0;
  if (config_.task_count > kMaxThreads - config_.first_thread)
    config_.task_count = kMaxThreads - config_.first_thread;
}

void PhaseRoundRobin::reset() {
  last_turn_ = kNoThread;
  holder_ = kNoThread;
}

void PhaseRoundRobin::lock(uint32_t thread) {
  if (holder_ == kNoThread && is_task(thread)) holder_ = thread;
}

void PhaseRoundRobin::unlock(uint32_t thread) {
  if (thread == holder_) holder_ = kNoThread;
}

bool PhaseRoundRobin::take_turn(vm::Machine& machine, uint32_t thread, PhaseResult& out) {
  const vm::ThreadStatus status = machine.status(thread);
  if (status != vm::ThreadStatus::Running && status != vm::ThreadStatus::Waiting) return false;
  const uint64_t lines = status == vm::ThreadStatus::Waiting ? 2 : 1;
  running_ = thread;
  const LineStep step = step_lines(machine, thread, lines, config_.back_jump_cap);
  running_ = kNoThread;
  report_step(out.report, thread, step);
  if (!step.ran) return false;
  out.turn = thread;
  last_turn_ = thread;
  return true;
}

PhaseResult PhaseRoundRobin::phase(vm::Machine& machine) {
  PhaseResult out;
  if (holder_ != kNoThread) {
    if (!has_ended(machine.status(holder_))) {
      // The holder keeps every phase, also while it sleeps or is halted: the phase passes idle.
      take_turn(machine, holder_, out);
      return out;
    }
    holder_ = kNoThread;  // its end released the lock
  }
  const uint32_t count = config_.task_count;
  if (count == 0) return out;
  const uint32_t after = last_turn_ == kNoThread ? count - 1 : last_turn_ - config_.first_thread;
  for (uint32_t k = 1; k <= count; ++k) {
    const uint32_t thread = config_.first_thread + (after + k) % count;
    if (take_turn(machine, thread, out)) break;
  }
  return out;
}

}  // namespace uprog::scheduling
