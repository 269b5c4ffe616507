// Every due thread one line a cycle, in thread order; due from its start every k-th cycle.
#include "dialect/scheduling/rate_priorities.h"

#include "dialect/scheduling/line_step.h"

namespace uprog::scheduling {

RatePriorities::RatePriorities(RatePrioritiesConfig config) : config_(config) {
  // A report names at most kMaxThreads threads.
  if (config_.first_thread >= kMaxThreads) config_.thread_count = 0;
  if (config_.thread_count > kMaxThreads - config_.first_thread)
    config_.thread_count = kMaxThreads - config_.first_thread;
  const uint32_t count = config_.thread_count;
  covered_ = (count == kMaxThreads ? ~0u : (1u << count) - 1) << config_.first_thread;
  reset();
}

void RatePriorities::reset() {
  cycle_ = 0;
  held_ = 0;
  slow_ = 0;
  started_now_ = 0;
  for (uint32_t t = 0; t < kMaxThreads; ++t) {
    priority_[t] = 1;
    start_cycle_[t] = 0;
  }
}

void RatePriorities::started(uint32_t thread) {
  if (!covers(thread)) return;
  start_cycle_[thread] = cycle_ + 1;
  started_now_ |= 1u << thread;
}

bool RatePriorities::set_priority(uint32_t thread, uint32_t priority) {
  if (!covers(thread) || priority < 1 || priority > kLowestRate) return false;
  priority_[thread] = priority;
  if (priority == 1)
    slow_ &= ~(1u << thread);
  else
    slow_ |= 1u << thread;
  return true;
}

uint32_t RatePriorities::priority(uint32_t thread) const {
  return covers(thread) ? priority_[thread] : 0;
}

void RatePriorities::hold(uint32_t thread) {
  if (covers(thread)) held_ |= 1u << thread;
}

void RatePriorities::release(uint32_t thread) {
  if (covers(thread)) held_ &= ~(1u << thread);
}

void RatePriorities::take_turn(vm::Machine& machine, uint32_t thread, Report& report) {
  running_ = thread;
  report_step(report, thread, step_lines(machine, thread, 1, config_.back_jump_cap));
  running_ = kNoThread;
}

}  // namespace uprog::scheduling
