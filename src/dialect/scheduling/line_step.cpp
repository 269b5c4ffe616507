// One line at a time, with a program's bare end folded into its last line.
#include "dialect/scheduling/line_step.h"

#include "bytecode/opcodes.h"

namespace uprog::scheduling {

namespace {

// Where the next instruction ends the program without being part of any line (the thread
// stopped at a line end, so it is running).
bool at_bare_end(const vm::Machine& machine, uint32_t thread) {
  const uint32_t pc = machine.pc(thread);
  const bytecode::ImageView& image = machine.image();
  if (pc >= image.code.size()) return false;
  const bytecode::Op op = bytecode::word_op(image.code[pc]);
  return op == bytecode::Op::EXIT || (op == bytecode::Op::RET && machine.frame_count(thread) == 1);
}

vm::SliceEnd run_bare_end(vm::Machine& machine, uint32_t thread, uint64_t back_jump_cap) {
  return machine.run_slice(thread, vm::Budget{1, 0, back_jump_cap}).end;
}

}  // namespace

LineStep step_lines(vm::Machine& machine, uint32_t thread, uint64_t lines, uint64_t back_jump_cap) {
  const vm::ThreadStatus status = machine.status(thread);
  if (status != vm::ThreadStatus::Running && status != vm::ThreadStatus::Waiting) return {};
  // Most waits are not over: no slice for them (it would end Waiting, having run nothing).
  if (machine.sleeping(thread)) return {vm::SliceEnd::Waiting};
  vm::Budget budget = vm::Budget::of_lines(lines);
  budget.back_jumps = back_jump_cap;
  const bool was_waiting = status == vm::ThreadStatus::Waiting;
  if (was_waiting) budget.instructions = kCountOnly;
  const vm::SliceResult r = machine.run_slice(thread, budget);
  LineStep step{r.end, !was_waiting || r.executed > 0, r.lines};
  if (r.end == vm::SliceEnd::LineEnd && at_bare_end(machine, thread)) {
    step.end = run_bare_end(machine, thread, back_jump_cap);
  }
  return step;
}

}  // namespace uprog::scheduling
