// One line at a time, with a program's bare end folded into its last line: the parts of
// step_lines that a running thread's usual turn does not take.
#include "dialect/scheduling/line_step.h"

namespace uprog::scheduling {

vm::SliceEnd run_bare_end(vm::Machine& machine, uint32_t thread, uint64_t back_jump_cap) {
  return machine.run_slice(thread, vm::Budget{1, 0, back_jump_cap}).end;
}

LineStep step_waiting_lines(vm::Machine& machine, uint32_t thread, uint64_t lines,
                            uint64_t back_jump_cap) {
  if (machine.status(thread) != vm::ThreadStatus::Waiting) return {};
  // Most waits are not over: no slice for them (it would end Waiting, having run nothing).
  if (machine.sleeping(thread)) return {vm::SliceEnd::Waiting};
  // Counted, so that the step knows whether it ran anything (the wait may still hold).
  const vm::SliceResult r = machine.run_slice(thread, vm::Budget{kCountOnly, lines, back_jump_cap});
  return finish_step(machine, thread, r, r.executed > 0, back_jump_cap);
}

}  // namespace uprog::scheduling
