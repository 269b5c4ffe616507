// Virtual time: servo cycles of TS microseconds, each followed by one background slice of the
// user program (Timing), with auto-routines entered at the slice boundary (a line boundary).
#include "controller/controller_impl.h"

#include "vm/run_error.h"

namespace uprog::controller {

void Controller::Impl::advance(uint64_t duration_us) {
  residual_us += duration_us;
  for (;;) {
    const uint64_t period = axis->period_us() == 0 ? 50 : axis->period_us();
    if (residual_us < period) break;
    residual_us -= period;
    now_us_ += period;
    servo_cycle();
    background_slice();
  }
}

void Controller::Impl::servo_cycle() {
  const uint32_t drive_events = axis->step();
  if (!machine || drive_events == 0) return;
  const uint32_t events = auto_events_of_drive_events(drive_events);
  for (uint32_t e = 0; e < kAutoEventCount; ++e) {
    if ((events >> e) & 1u) autos.raise(e);
  }
}

void Controller::Impl::dispatch_auto_routines() {
  // A halted program takes no auto-routines until XC; they stay pending.
  const vm::ThreadStatus status = machine->status(kProgramThread);
  if (status == vm::ThreadStatus::Halted || status == vm::ThreadStatus::AtBreakpoint) return;
  autos.update_active(*machine, kProgramThread);
  while (auto event = autos.take_next()) {
    const uint32_t routine = *autos.routine_of(*event);
    if (machine->interrupt(kProgramThread, routine) != vm::RunError::None) {
      log(std::string(auto_event_name(*event)) + " could not be entered (no room on the call stack)");
      continue;
    }
    ever_run = true;
    autos.entered(*event, *machine, kProgramThread);
    log(std::string(auto_event_name(*event)) + " entered");
  }
}

std::string Controller::Impl::where(uint32_t pc) const {
  if (const bytecode::LineEntry* line = ram_decoded.line_at(pc)) {
    return line->file + ":" + std::to_string(line->line);
  }
  return "code word " + std::to_string(pc);
}

// A run-time error no try block caught: AUTO_PERR takes over, or the program stops (PS=0).
void Controller::Impl::on_run_time_error() {
  program_error = machine->last_error(kProgramThread);
  program_error_detail = machine->error_detail(kProgramThread);
  std::string text = "run-time error " + std::to_string(static_cast<int>(program_error)) + " (" +
                     vm::run_error_text(program_error) + ")";
  if (program_error == vm::RunError::CommandRefused) {
    text += ", drive error " + std::to_string(program_error_detail);
  }
  text += " at " + where(machine->pc(kProgramThread));
  const auto perr = autos.routine_of(kAutoPerr);
  // An error inside AUTO_PERR itself stops the program: entering it again would loop forever.
  if (!perr || autos.perr_active()) {
    log(text + "; the program stopped");
    autos.forget_activity();
    return;
  }
  log(text + "; AUTO_PERR entered");
  machine->interrupt(kProgramThread, *perr);  // a failed thread starts it afresh
  autos.entered_perr(*machine, kProgramThread);
}

void Controller::Impl::background_slice() {
  if (!machine) return;
  // The usual servo cycle has nothing pending and no auto-routine active: no bookkeeping.
  if (!autos.quiet()) dispatch_auto_routines();
  const vm::ThreadStatus before = machine->status(kProgramThread);
  if (before != vm::ThreadStatus::Running && before != vm::ThreadStatus::Waiting) return;
  vm::Budget budget = vm::Budget::of_lines(
      options.timing.unlimited ? options.timing.unlimited_line_cap : options.timing.lines_per_cycle);
  budget.back_jumps = options.timing.back_jump_cap;
  const vm::SliceResult r = machine->run_slice(kProgramThread, budget);
  if (r.end == vm::SliceEnd::Error) on_run_time_error();
  if (r.end == vm::SliceEnd::Finished) log("program finished");
  if (!autos.quiet()) autos.update_active(*machine, kProgramThread);
}

}  // namespace uprog::controller
