// The Gold background: after every servo cycle one slice of the user program (the whole-lines
// policy, scheduling/whole_lines.h), with auto-routines entered at the slice boundary (a line
// boundary).
#include "dialects/gold/firmware.h"
#include "vm/run_error.h"

namespace uprog::gold {

void Firmware::dispatch_auto_routines() {
  vm::Machine& m = *machine();
  // A halted program takes no auto-routines until XC; they stay pending.
  const vm::ThreadStatus status = m.status(kProgramThread);
  if (status == vm::ThreadStatus::Halted || status == vm::ThreadStatus::AtBreakpoint) return;
  autos_.update_active(m, kProgramThread);
  while (auto event = autos_.take_next()) {
    const uint32_t routine = *autos_.routine_of(*event);
    if (m.interrupt(kProgramThread, routine) != vm::RunError::None) {
      log(std::string(auto_event_name(*event)) +
          " could not be entered (no room on the call stack)");
      continue;
    }
    ever_run_ = true;
    autos_.entered(*event, m, kProgramThread);
    log(std::string(auto_event_name(*event)) + " entered");
  }
}

// A run-time error no try block caught: AUTO_PERR takes over, or the program stops (PS=0).
void Firmware::on_run_time_error() {
  vm::Machine& m = *machine();
  program_error_ = m.last_error(kProgramThread);
  debug_error_reported_ = false;  // DB##MS shows it until DB##ES reads it
  program_error_detail_ = m.error_detail(kProgramThread);
  std::string text = "run-time error " + std::to_string(static_cast<int>(program_error_)) + " (" +
                     vm::run_error_text(program_error_) + ")";
  if (program_error_ == vm::RunError::CommandRefused) {
    text += ", drive error " + std::to_string(program_error_detail_);
  }
  text += " at " + program_->where(m.pc(kProgramThread));
  const auto perr = autos_.routine_of(kAutoPerr);
  // An error inside AUTO_PERR itself stops the program: entering it again would loop forever.
  if (!perr || autos_.perr_active()) {
    log(text + "; the program stopped");
    autos_.forget_activity();
    return;
  }
  log(text + "; AUTO_PERR entered");
  m.interrupt(kProgramThread, *perr);  // a failed thread starts it afresh
  autos_.entered_perr(m, kProgramThread);
}

[[gnu::always_inline]] inline void Firmware::background_slice() {
  if (!program_) return;
  // The usual servo cycle has nothing pending and no auto-routine active: no bookkeeping.
  if (!autos_.quiet()) dispatch_auto_routines();
  vm::Machine& m = *machine();
  // The whole-lines policy's slice (scheduling::WholeLines::slice), without its report: this
  // runs every servo cycle, and the slice's end says all the firmware needs.
  const vm::ThreadStatus before = m.status(kProgramThread);
  if (before != vm::ThreadStatus::Running && before != vm::ThreadStatus::Waiting) return;
  // A step of the Elmo debugger runs to the nearest end of line (DB##SO, SI, SU).
  const vm::SliceResult r = m.run_slice(
      kProgramThread, debug_step_ == DebugStep::None ? slice_budget_ : vm::Budget::of_lines(1));
  if (debug_active_) after_debug_slice(r.end);
  if (r.end == vm::SliceEnd::Error) on_run_time_error();
  if (r.end == vm::SliceEnd::Finished) log("program finished");
  if (!autos_.quiet()) autos_.update_active(m, kProgramThread);
}

// Every servo cycle: the drive's events raise auto-routines (rarely), then the slice, inline.
void Firmware::cycle(const std::vector<uint32_t>& drive_events) {
  if (program_ && !drive_events.empty() && drive_events[0] != 0) raise_auto_events(drive_events[0]);
  background_slice();
}

void Firmware::raise_auto_events(uint32_t drive_events) {
  const uint32_t events = auto_events_of_drive_events(drive_events);
  for (uint32_t e = 0; e < kAutoEventCount; ++e) {
    if ((events >> e) & 1u) autos_.raise(e);
  }
}

}  // namespace uprog::gold
