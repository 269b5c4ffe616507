// What one call of a scheduling policy did to each thread: which threads ran and what ended
// them. The firmware reacts (log, event routines, faults); the policy interprets nothing.
#pragma once
#include <cstdint>

namespace uprog::scheduling {

// Threads a policy can name: a report keeps one bit per thread in a 32-bit mask.
constexpr uint32_t kMaxThreads = 32;
constexpr uint32_t kNoThread = UINT32_MAX;

// The thread whose code runs now: the schedule's, else the one a debugger's step runs outside it
// (dialect::Firmware::debug_runs), else kNoThread (a host line).
constexpr uint32_t running_now(uint32_t scheduled, uint32_t stepped) {
  return scheduled != kNoThread ? scheduled : stepped;
}

// One bit each, so that a report holds every event a thread had in one call.
enum class ThreadEvent : uint8_t {
  Finished = 1,    // the program ended (its outermost routine returned, or it exited)
  Error = 2,       // an uncaught run-time error stopped it (Machine::last_error says which)
  Breakpoint = 4,  // it stopped at a breakpoint
  Overrun = 8,     // a cyclic run needed more lines than its budget; the policy halted it
};

class Report {
 public:
  void mark_ran(uint32_t thread) {
    if (thread < kMaxThreads) ran_ |= 1u << thread;
  }
  void mark_ran_all(uint32_t threads) { ran_ |= threads; }  // one bit each
  void add(uint32_t thread, ThreadEvent event) {
    if (thread >= kMaxThreads) return;
    events_[thread] = static_cast<uint8_t>(events_[thread] | static_cast<uint8_t>(event));
    with_events_ |= 1u << thread;
  }

  // The threads that executed code in this call, one bit each.
  uint32_t ran() const { return ran_; }
  bool ran(uint32_t thread) const { return thread < kMaxThreads && ((ran_ >> thread) & 1u); }
  // The threads that have at least one event, one bit each.
  uint32_t threads_with_events() const { return with_events_; }
  bool has(uint32_t thread, ThreadEvent event) const {
    return thread < kMaxThreads && (events_[thread] & static_cast<uint8_t>(event)) != 0;
  }
  bool empty() const { return ran_ == 0 && with_events_ == 0; }

 private:
  uint32_t ran_ = 0;
  uint32_t with_events_ = 0;
  uint8_t events_[kMaxThreads] = {};
};

}  // namespace uprog::scheduling
