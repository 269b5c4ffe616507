// One step of a thread that counts source lines: the unit of a turn (PDL, Akribis) and of a
// cyclic task's line budget (ST). Shared by the policies that give threads lines one at a time.
#pragma once
#include <cstdint>

#include "dialect/scheduling/report.h"
#include "vm/machine.h"

namespace uprog::scheduling {

// An instruction budget that never stops a slice: set only so that the machine reports how
// many instructions ran (a waiting thread whose time has not come runs none).
constexpr uint64_t kCountOnly = uint64_t{1} << 62;

struct LineStep {
  vm::SliceEnd end = vm::SliceEnd::NotRunning;
  // False when nothing executed: the thread could not run, or its timed wait is not over.
  bool ran = false;
  uint64_t lines = 0;  // line ends passed (the bare end adds none)
};

// Runs `thread` through `lines` line ends (or to its end, a wait, a yield, a breakpoint, an
// uncaught error, or `back_jump_cap` jumps back, whichever comes first). A thread that is not
// running or waiting is left alone. The bare end of a program (a RET leaving the outermost
// frame, or an EXIT, where a line would start) is no line of its own: it runs with the line
// before it, so a thread ends in the step of its last line (a fresh start of an empty routine
// ends in a step of its own). Inline below for a running thread (a drive's turn, several a cycle).
LineStep step_lines(vm::Machine& machine, uint32_t thread, uint64_t lines, uint64_t back_jump_cap);

// The slice of the bare end after a line.
vm::SliceEnd run_bare_end(vm::Machine& machine, uint32_t thread, uint64_t back_jump_cap);

// The step a slice made; a bare end after its line runs with it.
inline LineStep finish_step(vm::Machine& machine, uint32_t thread, const vm::SliceResult& r,
                            bool ran, uint64_t back_jump_cap) {
  LineStep step{r.end, ran, r.lines};
  if (r.end == vm::SliceEnd::LineEnd && machine.at_bare_end(thread))
    step.end = run_bare_end(machine, thread, back_jump_cap);
  return step;
}

// step_lines for a thread that is not running: waiting, or not to be run at all.
LineStep step_waiting_lines(vm::Machine& machine, uint32_t thread, uint64_t lines,
                            uint64_t back_jump_cap);

inline LineStep step_lines(vm::Machine& machine, uint32_t thread, uint64_t lines,
                           uint64_t back_jump_cap) {
  if (machine.status(thread) != vm::ThreadStatus::Running)
    return step_waiting_lines(machine, thread, lines, back_jump_cap);
  const vm::SliceResult r = machine.run_slice(thread, vm::Budget{0, lines, back_jump_cap});
  return finish_step(machine, thread, r, true, back_jump_cap);
}

// Adds what a step ended with to the report: Finished, Error or Breakpoint; and that it ran.
// Inline: every due thread's step of every cycle comes through here.
inline void report_step(Report& report, uint32_t thread, const LineStep& step) {
  if (step.ran) report.mark_ran(thread);
  switch (step.end) {
    case vm::SliceEnd::Finished:
      return report.add(thread, ThreadEvent::Finished);
    case vm::SliceEnd::Error:
      return report.add(thread, ThreadEvent::Error);
    case vm::SliceEnd::Breakpoint:
      return report.add(thread, ThreadEvent::Breakpoint);
    default:
      return;
  }
}

}  // namespace uprog::scheduling
