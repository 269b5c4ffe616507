// The Elmo debugger's commands on Gold's command line (SimplIQ software manual 6.7): DB##BP=pc[,n]
// and DB##BC[=pc] set and clear breakpoints at code words, DB##GO[N] continues, DB##SO, SI and
// SU[N] step over, in and out to the nearest end of line, DB##MS, PS[N] and ES[N] report. The
// program has one VAC machine, handle 0; docs/debugging.md has the formats.
#include <fmt/core.h>

#include <charconv>

#include "dialects/gold/firmware.h"

namespace uprog::gold {

using dialect::Answer;

namespace {

constexpr size_t kMaxBreakpoints = 6;  // five of the user's and one for the IDE (6.7.7)

// The manual's machine status (6.7.4): 0 halted, 1 running, 2 idle, 3 aborted, 4 does not exist.
uint32_t machine_status(vm::ThreadStatus s) {
  switch (s) {
    case vm::ThreadStatus::Halted:
    case vm::ThreadStatus::AtBreakpoint:
      return 0;
    case vm::ThreadStatus::Running:
    case vm::ThreadStatus::Waiting:
      return 1;
    case vm::ThreadStatus::Idle:
      return 2;
    case vm::ThreadStatus::Error:
      return 3;
  }
  return 2;
}

bool parse_u32(std::string_view text, uint32_t& out) {
  const auto [p, e] = std::from_chars(text.data(), text.data() + text.size(), out);
  return !text.empty() && e == std::errc() && p == text.data() + text.size();
}

// "[N]" after a command, or nothing: the machine's handle; false when it names another one.
bool handle_is_ours(std::string_view rest) {
  if (rest.empty()) return true;
  return rest == "[0]";
}

}  // namespace

void Firmware::forget_debug_state_of_another_program() {
  if (debug_generation_ == program_generation_) return;
  debug_generation_ = program_generation_;
  debug_breakpoints_.clear();
  debug_step_ = DebugStep::None;
  debug_active_ = false;
  debug_error_reported_ = false;
}

bool Firmware::debug_command(const std::string& word, std::vector<Answer>& answers) {
  const std::string name = word.substr(0, 2);
  if (name != "BP" && name != "BC" && name != "GO" && name != "SO" && name != "SI" &&
      name != "SU" && name != "MS" && name != "PS" && name != "ES") {
    return false;
  }
  auto fail = [&](int32_t code, const std::string& why) {
    answers.push_back(error_answer(code, why));
  };
  if (!program_) return fail(kErrorNoProgram, "no program is loaded"), true;
  forget_debug_state_of_another_program();
  vm::Machine& m = *machine();
  const std::string rest = word.substr(2);
  const vm::ThreadStatus status = m.status(kProgramThread);

  if (name == "BP" || name == "BC") {
    if (name == "BC" && rest.empty()) {
      for (const DebugBreakpoint& b : debug_breakpoints_) m.clear_breakpoint(b.pc);
      debug_breakpoints_.clear();
    } else {
      uint32_t pc = 0, n = 1;
      const size_t comma = rest.find(',');
      const bool shaped = rest.size() > 1 && rest[0] == '=' &&
                          parse_u32(rest.substr(1, comma - 1), pc) &&
                          (name == "BP" || comma == std::string::npos) &&
                          (comma == std::string::npos ||
                           (parse_u32(rest.substr(comma + 1), n) && n >= 1 && n <= 32767));
      if (!shaped)
        return fail(kErrorSyntax, "DB##BP=pc[,n] or DB##BC[=pc], pc a code word, n 1..32767"), true;
      std::erase_if(debug_breakpoints_, [&](const DebugBreakpoint& b) {
        if (b.pc == pc) m.clear_breakpoint(pc);
        return b.pc == pc;
      });
      if (name == "BP") {
        if (debug_breakpoints_.size() >= kMaxBreakpoints)
          return fail(kErrorOutOfRange, "six breakpoints are set"), true;
        if (!m.set_breakpoint(pc))
          return fail(kErrorOutOfRange, fmt::format("code word {} starts no instruction", pc)),
                 true;
        debug_breakpoints_.push_back({pc, static_cast<int32_t>(n), 0});
      }
    }
  } else if (name == "GO" || name == "SO" || name == "SI" || name == "SU") {
    if (!handle_is_ours(rest))
      return fail(kErrorBadIndex, "the program has one VAC machine, 0"), true;
    if (status != vm::ThreadStatus::Halted && status != vm::ThreadStatus::AtBreakpoint) {
      return fail(kErrorNotHalted, "the program is not halted"), true;
    }
    debug_step_ = name == "GO"   ? DebugStep::None
                  : name == "SO" ? DebugStep::Over
                  : name == "SI" ? DebugStep::In
                                 : DebugStep::Out;
    debug_step_depth_ = m.frame_count(kProgramThread);
    m.resume(kProgramThread);
  } else if (name == "MS") {
    if (!rest.empty()) return fail(kErrorSyntax, "DB##MS takes no index"), true;
    // Four bits a machine, machine 0 lowest; bit 3 a run-time error DB##ES has not read.
    uint32_t nibble = machine_status(status);
    if (status == vm::ThreadStatus::Error && !debug_error_reported_) nibble |= 8;
    answers.push_back(Answer{fmt::format("{:04X}", 0x4440u | nibble), 0});
  } else if (name == "PS") {
    if (!handle_is_ours(rest))
      return fail(kErrorBadIndex, "the program has one VAC machine, 0"), true;
    // Status, error code, program counter, base pointer (here: the call depth), stack pointer
    // (the VM keeps none a host could use: 0), each 16 bits, as 4 hex digits.
    const uint32_t error =
        status == vm::ThreadStatus::Error ? static_cast<uint32_t>(m.last_error(kProgramThread)) : 0;
    answers.push_back(
        Answer{fmt::format("{:04X}{:04X}{:04X}{:04X}{:04X}", machine_status(status), error,
                           m.pc(kProgramThread) & 0xFFFFu, m.frame_count(kProgramThread), 0u),
               0});
  } else {  // ES
    if (!handle_is_ours(rest))
      return fail(kErrorBadIndex, "the program has one VAC machine, 0"), true;
    debug_error_reported_ = true;
    answers.push_back(Answer{std::to_string(static_cast<int>(m.last_error(kProgramThread))), 0});
  }
  debug_active_ = !debug_breakpoints_.empty() || debug_step_ != DebugStep::None;
  return true;
}

// After a background slice while the debugger has breakpoints or a step.
void Firmware::after_debug_slice(vm::SliceEnd end) {
  forget_debug_state_of_another_program();
  vm::Machine& m = *machine();
  if (end == vm::SliceEnd::Breakpoint) {
    for (DebugBreakpoint& b : debug_breakpoints_) {
      if (b.pc != m.pc(kProgramThread)) continue;
      if (++b.hits < b.stop_at_hit) {
        m.resume(kProgramThread);  // not yet: on in the next cycle
      } else {
        debug_step_ = DebugStep::None;
        log(fmt::format("breakpoint at code word {} (hit {})", b.pc, b.hits));
      }
    }
  } else if (debug_step_ != DebugStep::None) {
    const uint32_t depth = m.frame_count(kProgramThread);
    const bool done = end == vm::SliceEnd::LineEnd &&
                      (debug_step_ == DebugStep::In ||
                       (debug_step_ == DebugStep::Over && depth <= debug_step_depth_) ||
                       (debug_step_ == DebugStep::Out && depth < debug_step_depth_));
    if (done) m.halt(kProgramThread);
    if (done || end == vm::SliceEnd::Finished || end == vm::SliceEnd::Error)
      debug_step_ = DebugStep::None;
  }
  debug_active_ = !debug_breakpoints_.empty() || debug_step_ != DebugStep::None;
}

}  // namespace uprog::gold
