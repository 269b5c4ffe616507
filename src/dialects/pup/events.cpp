// The AG300's events (the spec's IDs 0..23): latched when linked (#event), enabled by
// AProgEventMask and seen while thread 1 runs or waits; taken lowest first on thread 1, threads
// 2..8 held until the event function returns. Mask bit 31 lets an event function be interrupted.
#include "drive/events.h"

#include <fmt/core.h>

#include "dialects/pup/firmware.h"
#include "drive/axis.h"

namespace uprog::pup {
namespace {

constexpr uint32_t kNestingBit = 1u << 31;

}  // namespace

void Firmware::latch(int32_t id) {
  if (!program_ || id < 0 || id > 23) return;
  // Only while the main thread runs or waits: an edge seen while it is idle or halted is not
  // kept for later.
  if (const int32_t s = program_status(1); s != 1 && s != 2) return;
  if (cup_.event_routine[static_cast<size_t>(id)] < 0 || ((event_mask_ >> id) & 1u) == 0) return;
  latched_ |= 1u << id;
}

void Firmware::latch_events(uint32_t drive_events) {
  const drive::Axis& a = *axis_;
  if (drive_events & drive::kEventFault) latch(0);
  if (drive_events & drive::kEventForwardLimit) latch(1);
  if (drive_events & drive::kEventReverseLimit) latch(2);
  const drive::Parameters& p = a.parameters();
  const int32_t reference = a.reference_position();
  const bool above = reference >= p.position_high_counts;
  const bool below = reference <= p.position_low_counts;
  if (above && !above_max_) latch(3);
  if (below && !below_min_) latch(4);
  above_max_ = above, below_min_ = below;
  const bool moving = a.profiler_moving();
  if (was_moving_ && !moving) latch(5);
  was_moving_ = moving;
  const uint32_t levels = a.input_level_bits();
  if (levels == previous_inputs_) return;  // no edge: most cycles
  for (int n = 0; n < 6; ++n) {
    const bool now = (levels >> n) & 1u, before = (previous_inputs_ >> n) & 1u;
    if (now && !before) latch(6 + n);
    if (!now && before) latch(12 + n);
  }
  previous_inputs_ = levels;
}

void Firmware::take_event() {
  const int32_t s = program_status(1);
  if (s != 1 && s != 2) return;
  if (!event_frames_.empty() && (event_mask_ & kNestingBit) == 0) return;
  int32_t id = 0;
  while (((latched_ >> id) & 1u) == 0) ++id;
  latched_ &= ~(1u << id);
  vm::Machine& m = program_->machine();
  if (m.interrupt(1, static_cast<uint32_t>(cup_.event_routine[static_cast<size_t>(id)])) !=
      vm::RunError::None) {
    log_error(28, 1, static_cast<int32_t>(cup_.line_of(m.pc(1))));
    return;
  }
  event_mask_ &= ~kNestingBit;
  uint32_t held_before = 0;
  for (uint32_t t = 2; t <= kThreads; ++t) held_before |= schedule_.held(t) ? 1u << t : 0;
  event_frames_.push_back({m.frame_count(1), held_before});
  for (uint32_t t = 2; t <= kThreads; ++t) schedule_.hold(t);
  runtime_.log(fmt::format("event {} entered", id));
}

// An event function has returned when thread 1 is back below its frame; the last one out
// releases the held threads. An error or a halt of thread 1 ends them all.
void Firmware::check_event_return() {
  const vm::Machine& m = program_->machine();
  const int32_t s = program_status(1);
  if (s != 1 && s != 2 && s != 6) {
    if (s != 3 && s != 4) reset_events();  // a halt or breakpoint keeps the event for resuming
    return;
  }
  // Each event returned from gives back the threads as they were when it entered: an outer event
  // function's `AProgRun[t],-1` stays in force after a nested one returns.
  while (!event_frames_.empty() && m.frame_count(1) < event_frames_.back().frames) {
    const uint32_t held_before = event_frames_.back().held_before;
    event_frames_.pop_back();
    for (uint32_t t = 2; t <= kThreads; ++t) {
      if ((held_before >> t) & 1u)
        schedule_.hold(t);
      else
        schedule_.release(t);
    }
  }
}

void Firmware::reset_events() {
  event_frames_.clear();
  schedule_.release_all();
}

}  // namespace uprog::pup
