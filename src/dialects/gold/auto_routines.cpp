// Auto-routine precedence and masking (manual 2.14); see auto_routines.h.
#include "dialects/gold/auto_routines.h"

#include "drive/events.h"

namespace uprog::gold {

const char* auto_event_name(uint32_t event) {
  static constexpr const char* kNames[kAutoEventCount] = {
      "AUTOEXEC", "AUTO_ER", "AUTO_STOP", "AUTO_BG",  "AUTO_RLS", "AUTO_FLS",
      "AUTO_ENA", "AUTO_I1", "AUTO_I2",   "AUTO_I3",  "AUTO_I4",  "AUTO_I5",
      "AUTO_I6",  "AUTO_HM", "AUTO_HY",   "AUTO_PERR"};
  return event < kAutoEventCount ? kNames[event] : "?";
}

uint32_t auto_events_of_drive_events(uint32_t e) {
  uint32_t out = 0;
  if (e & drive::kEventReverseLimit) out |= 1u << kAutoRls;
  if (e & drive::kEventForwardLimit) out |= 1u << kAutoFls;
  if (e & drive::kEventHardStop) out |= 1u << kAutoStop;
  if (e & drive::kEventInhibitReleased) out |= 1u << kAutoEna;
  if (e & drive::kEventBegin) out |= 1u << kAutoBg;
  if (e & drive::kEventHome) out |= 1u << kAutoHm;
  if (e & drive::kEventFault) out |= 1u << kAutoEr;
  for (int n = 1; n <= 6; ++n) {
    if (e & drive::general_input_event(n)) out |= 1u << (kAutoI1 + static_cast<uint32_t>(n) - 1);
  }
  return out;
}

void AutoRoutines::clear() {
  routine_.fill(-1);
  mask_ = 0;
  perr_block_ = false;
  forget_activity();
}

void AutoRoutines::bind(const bytecode::ImageView& image) {
  clear();
  for (uint32_t i = 0; i < image.events.size(); ++i) {
    const bytecode::EventRecord r = image.events[i];
    if (r.event < kAutoEventCount && r.routine < image.routines.size()) {
      routine_[r.event] = static_cast<int32_t>(r.routine);
    }
  }
}

std::optional<uint32_t> AutoRoutines::routine_of(uint32_t event) const {
  if (event >= kAutoEventCount || routine_[event] < 0) return std::nullopt;
  return static_cast<uint32_t>(routine_[event]);
}

void AutoRoutines::raise(uint32_t event) {
  if (!routine_of(event)) return;
  // A masked event is lost, not deferred: a real drive does not queue what MI disables.
  if (event != kAutoPerr && ((mask_ >> event) & 1u) != 0) return;
  if (event != kAutoPerr && perr_block_) return;
  pending_ |= 1u << event;
}

void AutoRoutines::forget_activity() {
  pending_ = 0;
  active_.clear();
}

int AutoRoutines::precedence(uint32_t event) {
  return event == kAutoPerr ? -1 : static_cast<int>(event);
}

void AutoRoutines::update_active(const vm::Machine& machine, uint32_t thread) {
  if (active_.empty()) return;
  const vm::ThreadStatus status = machine.status(thread);
  while (!active_.empty()) {
    const Active& a = active_.back();
    const uint32_t count = machine.frame_count(thread);
    bool gone =
        status == vm::ThreadStatus::Idle || status == vm::ThreadStatus::Error || count < a.depth;
    // `reset` drops every frame and starts another routine at the same depth.
    if (!gone && machine.frame(thread, count - a.depth).routine != a.routine) gone = true;
    if (!gone) break;
    active_.pop_back();
  }
}

std::optional<uint32_t> AutoRoutines::take_next() {
  if (pending_ == 0) return std::nullopt;
  uint32_t best = kAutoEventCount;
  for (uint32_t e = 0; e < kAutoEventCount; ++e) {
    if (((pending_ >> e) & 1u) == 0) continue;
    if (best == kAutoEventCount || precedence(e) < precedence(best)) best = e;
  }
  // It interrupts only what is less urgent; otherwise it waits for the active one to return.
  for (const Active& a : active_) {
    if (precedence(a.event) <= precedence(best)) return std::nullopt;
  }
  pending_ &= ~(1u << best);
  return best;
}

void AutoRoutines::entered(uint32_t event, const vm::Machine& machine, uint32_t thread) {
  active_.push_back({event, static_cast<uint32_t>(routine_[event]), machine.frame_count(thread)});
}

void AutoRoutines::entered_perr(const vm::Machine& machine, uint32_t thread) {
  forget_activity();
  perr_block_ = true;
  entered(kAutoPerr, machine, thread);
}

bool AutoRoutines::perr_active() const {
  for (const Active& a : active_) {
    if (a.event == kAutoPerr) return true;
  }
  return false;
}

}  // namespace uprog::gold
