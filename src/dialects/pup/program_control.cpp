// AProgSingle, AProgBreaks, AProgCallStack, AProgExpStack, AProgPointer=, AProgClrCall and
// AProgClrExp. A single step lets the halted thread run in its own turns until it has executed
// one line (Type 0) or left the line at its call depth (else, stepping over calls and waits),
// then halts it again. Breakpoints are per thread: the VM traps any thread at the line, and one
// without the line in its list goes on.
#include <fmt/core.h>

#include <algorithm>
#include <span>
#include <vector>

#include "bytecode/opcodes.h"
#include "dialects/pup/firmware.h"

namespace uprog::pup {

int32_t Firmware::single_step(uint32_t thread, int32_t kind) {
  if (program_status(thread) != 3 && program_status(thread) != 4) return 19;
  vm::Machine& m = program_->machine();
  // Back from a call (after stepping an AReturn), the thread stands on the end of the call's
  // line, which is no step of its own: the step starts at the next line.
  const uint32_t line = next_line(thread);
  if (line != cup_.line_of(m.pc(thread)) && line >= 1 && line <= cup_program_.lines.size()) {
    std::vector<uint32_t> scratch(bytecode::verify_scratch_size(m.image()) / sizeof(uint32_t) + 1);
    m.move_pc(thread, cup_.line_pc[line], scratch.data(), scratch.size() * sizeof(uint32_t));
  }
  single_[thread] = Single{kind != 0, line, m.frame_count(thread)};
  stepping_ |= 1u << thread;
  m.resume(thread);
  return 0;
}

void Firmware::after_cycle(const scheduling::Report& report) {
  vm::Machine& m = program_->machine();
  for (uint32_t t = 1; t <= kThreads; ++t) {
    const uint32_t bit = 1u << t;
    if (report.has(t, scheduling::ThreadEvent::Breakpoint)) {
      const uint32_t line = next_line(t);
      if (!break_line_in_use(line)) {
        // Not a ProgBreaks line: the debugger's trap (src/debug), which it handles.
      } else if (!std::binary_search(breaks_[t].begin(), breaks_[t].end(), line)) {
        m.resume(t);
      } else {
        stepping_ &= ~bit;
      }
    }
    if ((stepping_ & bit) == 0) continue;
    const Single& s = single_[t];
    const int32_t status = program_status(t);
    if (status != 1 && status != 2) {
      stepping_ &= ~bit;
      continue;
    }
    const bool done = s.over ? status != 2 && m.frame_count(t) <= s.depth && next_line(t) != s.line
                             : report.ran(t);
    if (done) {
      m.halt(t);
      stepping_ &= ~bit;
    }
  }
}

bool Firmware::break_line_in_use(uint32_t line) const {
  for (uint32_t t = 1; t <= kThreads; ++t) {
    if (std::binary_search(breaks_[t].begin(), breaks_[t].end(), line)) return true;
  }
  return false;
}

int32_t Firmware::set_breaks(uint32_t thread, int32_t value) {
  std::vector<uint32_t>& list = breaks_[thread];
  vm::Machine& m = program_->machine();
  auto in_use = [&](uint32_t line) { return break_line_in_use(line); };
  auto unset = [&](uint32_t line) {
    list.erase(std::find(list.begin(), list.end(), line));
    if (!in_use(line)) m.clear_breakpoint(cup_.line_pc[line]);
  };
  if (value == 0) {
    while (!list.empty()) unset(list.back());
    return 0;
  }
  const uint32_t line = static_cast<uint32_t>(value < 0 ? -static_cast<int64_t>(value) : value);
  if (line > cup_program_.lines.size()) return 32;
  const bool present = std::binary_search(list.begin(), list.end(), line);
  if (value < 0) {
    if (present) unset(line);
    return 0;
  }
  if (present) return 0;
  if (list.size() >= 16) return 34;
  if (!in_use(line) && !m.set_breakpoint(cup_.line_pc[line])) return 34;
  list.insert(std::upper_bound(list.begin(), list.end(), line), line);
  return 0;
}

// Clearing a stack of a thread that is not running leaves it idle; thread 0's is the host's.
int32_t Firmware::clear_stacks(uint32_t thread, bool expression_stack) {
  if (thread == 0) {
    if (expression_stack) line_stack_.clear();
    return 0;
  }
  if (!program_) return 0;
  const int32_t s = program_status(thread);
  if (s == 1 || s == 2 || s == 6) return 17;
  program_->machine().kill(thread);
  stepping_ &= ~(1u << thread);
  return 0;
}

std::string Firmware::breaks_list(uint32_t thread) const {
  std::string out;
  for (uint32_t l : breaks_[thread]) out += (out.empty() ? "" : ",") + std::to_string(l);
  return out;
}

// The lines each caller resumes at, innermost first.
std::string Firmware::call_stack(uint32_t thread) const {
  std::string out;
  if (!program_ || program_status(thread) == 0) return out;
  const vm::Machine& m = program_->machine();
  const auto& code = m.image().code;
  for (uint32_t d = 1; d < m.frame_count(thread); ++d) {
    uint32_t pc = m.frame(thread, d).pc;
    if (pc < code.size() && bytecode::word_op(code[pc]) == bytecode::Op::EOL) ++pc;
    out += (out.empty() ? "" : ",") + std::to_string(cup_.line_of(pc));
  }
  return out;
}

// AProgExpStack[t]: the thread's expression stack, top first; thread 0's is the line's. A thread
// that runs has none to show (17).
int32_t Firmware::expression_stack(uint32_t thread, std::string& list) const {
  const auto add = [&](int32_t v) { list += (list.empty() ? "" : ",") + std::to_string(v); };
  if (thread == 0) {
    for (auto it = line_stack_.rbegin(); it != line_stack_.rend(); ++it) add(*it);
    return 0;
  }
  if (!program_) return 0;
  const int32_t s = program_status(thread);
  if (s == 1 || s == 2 || s == 6) return 17;
  const std::span<const Value> stack = program_->machine().operand_stack(thread);
  for (auto it = stack.rbegin(); it != stack.rend(); ++it) add(it->i);
  return 0;
}

// AProgPointer[t]=line: a halted thread goes on from the line; an idle one stands halted at it,
// in the first task whose own code reaches it. The line must be one the thread can stand on as
// it is: at its call depth and with its expression stack as deep as the loader found the line's
// (32 otherwise), as the VM checks; 19 for a thread neither halted nor idle.
int32_t Firmware::set_pointer(uint32_t thread, int32_t line) {
  if (!program_) return 15;
  const int32_t s = program_status(thread);
  if (s != 0 && s != 3) return 19;
  if (line < 1 || static_cast<size_t>(line) + 1 >= cup_.line_pc.size()) return 32;
  vm::Machine& m = program_->machine();
  const uint32_t pc = cup_.line_pc[static_cast<size_t>(line)];
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(m.image()) / sizeof(uint32_t) + 1);
  const size_t scratch_bytes = scratch.size() * sizeof(uint32_t);
  stepping_ &= ~(1u << thread);
  if (s == 3) return m.move_pc(thread, pc, scratch.data(), scratch_bytes) ? 0 : 32;
  for (const int32_t routine : cup_.task_routine) {
    if (routine < 0) continue;
    m.start(thread, static_cast<uint32_t>(routine));
    m.halt(thread);
    if (m.move_pc(thread, pc, scratch.data(), scratch_bytes)) {
      schedule_.started(thread);
      thread_error_[thread] = 0;
      return 0;
    }
    m.kill(thread);
  }
  return 32;
}

}  // namespace uprog::pup
