// Whole lines per slice: the budget is lines (free per instruction), capped by jumps back.
#include "dialect/scheduling/whole_lines.h"

#include "dialect/scheduling/line_step.h"

namespace uprog::scheduling {

vm::Budget WholeLines::budget() const {
  vm::Budget budget = vm::Budget::of_lines(timing_.unlimited ? timing_.unlimited_line_cap
                                                             : timing_.lines_per_cycle);
  budget.back_jumps = timing_.back_jump_cap;
  return budget;
}

Report WholeLines::slice(vm::Machine& machine, uint32_t thread) const {
  Report report;
  const vm::ThreadStatus status = machine.status(thread);
  if (status != vm::ThreadStatus::Running && status != vm::ThreadStatus::Waiting) return report;
  vm::Budget b = budget();
  // Only a waiting thread's slice counts instructions, to tell whether its wait was over.
  const bool was_waiting = status == vm::ThreadStatus::Waiting;
  if (was_waiting) b.instructions = kCountOnly;
  const vm::SliceResult r = machine.run_slice(thread, b);
  report_step(report, thread, {r.end, !was_waiting || r.executed > 0});
  return report;
}

}  // namespace uprog::scheduling
