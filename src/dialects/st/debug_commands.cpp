// The S300's debug commands on the ASCII line (docs/dialects/st.md, "Debug commands"): PLCSTAT
// lists each PLC program's state and line; PLCHOLD and PLCCONT hold a program where it stands and
// let it go on (every program when no name is given); PLCSTEP runs a held program's next line.
#include <fmt/core.h>

#include "dialects/st/firmware.h"
#include "dialects/st/names.h"

namespace uprog::st {

using dialect::Answer;

bool is_debug_command(std::string_view name) {
  return name == "PLCSTAT" || name == "PLCHOLD" || name == "PLCCONT" || name == "PLCSTEP";
}

std::string Firmware::program_state(uint32_t thread) const {
  const vm::Machine& m = program_->machine();
  const vm::ThreadStatus s = m.status(thread);
  if (!schedule_.started() || schedule_.stopped(thread) || s == vm::ThreadStatus::Error)
    return "stopped";
  if (s == vm::ThreadStatus::AtBreakpoint) return "break";
  if (schedule_.held(m, thread)) return "held";
  if (s == vm::ThreadStatus::Idle) return "idle";
  return s == vm::ThreadStatus::Waiting ? "wait" : "run";
}

std::vector<Answer> Firmware::debug_command(const std::string& name,
                                            const std::vector<std::string>& words) {
  if (!program_) return {Answer{"no PLC program", kErrCompileFailed}};
  vm::Machine& m = program_->machine();
  if (name == "PLCSTAT") {
    std::vector<Answer> out;
    for (const auto& [thread, program] : threads_) {
      const bool placed = m.status(thread) != vm::ThreadStatus::Idle;
      out.push_back(Answer{fmt::format("{} {} {}", program, program_state(thread),
                                       placed ? program_->place(m.pc(thread)) : "-"),
                           0});
    }
    return out;
  }
  if (words.size() > 2 || (name == "PLCSTEP" && words.size() != 2))
    return {Answer{"syntax error", kErrSyntax}};
  if (plc_state() != 1) return {Answer{"PLC not running", kErrPlcStopped}};
  std::vector<uint32_t> chosen;
  for (const auto& [thread, program] : threads_)
    if (words.size() == 1 || upper(words[1]) == program) chosen.push_back(thread);
  if (chosen.empty()) return {Answer{"no such PLC program", kErrRange}};
  if (name == "PLCHOLD") {
    for (uint32_t thread : chosen) schedule_.hold(m, thread);
    return {};
  }
  if (name == "PLCCONT") {
    for (uint32_t thread : chosen) schedule_.release(m, thread);
    return {};
  }
  const uint32_t thread = chosen.front();
  if (!schedule_.held(m, thread)) return {Answer{"not held", kErrNotHeld}};
  scheduling::Report report;
  if (!schedule_.step_held(m, thread, report)) return {Answer{"no line to run", kErrNotHeld}};
  on_report(report);
  return {};
}

}  // namespace uprog::st
