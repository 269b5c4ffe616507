// PDL's own debug lines on the host protocol (docs/dialects/pdl.md, "Debug lines"), in the form
// of run/t and kill/t: `stat/t` a task's state and place, `hold/t` holds it where it stands,
// `cont/t` lets it go on, `step/t` runs a held task's next command and holds it again. Task 0 of
// hold and cont is every task.
#include <algorithm>
#include <charconv>

#include "dialects/pdl/firmware.h"
#include "dialects/pdl/system_names.h"

namespace uprog::pdl {
namespace {

using dialect::Answer;

constexpr int32_t kNotHeld = 13;                   // step/t of a task that is not held
constexpr uint32_t kMaxGlueInstructions = 10'000;  // a procedure zeroes at most 256 locals

bool held(vm::ThreadStatus s) {
  return s == vm::ThreadStatus::Halted || s == vm::ThreadStatus::AtBreakpoint;
}

}  // namespace

bool Firmware::debug_line(std::string_view text, std::vector<Answer>& answers) {
  static constexpr std::string_view kVerbs[] = {"stat/", "hold/", "cont/", "step/"};
  std::string_view verb;
  for (std::string_view v : kVerbs)
    if (text.size() > v.size() && equal_ignoring_case(text.substr(0, v.size()), v)) verb = v;
  if (verb.empty()) return false;
  std::string_view number = text.substr(verb.size());
  while (!number.empty() && number.back() == ' ') number.remove_suffix(1);
  int32_t t = -1;
  const auto [p, e] = std::from_chars(number.data(), number.data() + number.size(), t);
  const bool all_allowed = verb == "hold/" || verb == "cont/";
  if (e != std::errc() || p != number.data() + number.size() || t < (all_allowed ? 0 : 1) ||
      t > static_cast<int32_t>(kTasks)) {
    answers.push_back(
        {all_allowed ? "the task is 0 (all), 1, 2 or 3" : "the task is 1, 2 or 3", kBadTask});
    return true;
  }
  if (!program_) {
    answers.push_back({"no program", kNoProgram});
    return true;
  }
  vm::Machine& m = *machine();
  const auto task = static_cast<uint32_t>(t);
  if (verb == "stat/") {
    // task_st's number (4 held), then where it stands.
    const std::string where =
        m.status(task) != vm::ThreadStatus::Idle ? program_->place(m.pc(task)) : "-";
    answers.push_back({std::to_string(task_state(task)) + " " + where, 0});
    return true;
  }
  for (uint32_t k = task == 0 ? 1 : task; k <= (task == 0 ? kTasks : task); ++k) {
    const vm::ThreadStatus s = m.status(k);
    if (verb == "hold/" && (s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting))
      m.halt(k);
    if (verb == "cont/" && held(s)) m.resume(k);
  }
  if (verb != "step/") return true;
  if (!held(m.status(task))) {
    answers.push_back({"the task is not held", kNotHeld});
    return true;
  }
  // Its next command, as its turn would run it (up to the command's end or a wait inside it).
  // Then on to the next command's start, through what joins commands without a command of its own
  // (a procedure call's CALL and the zeroing of its locals, a loop's jump back, the return
  // dispatch).
  m.resume(task);
  vm::SliceResult r = m.run_slice(task, vm::Budget::of_lines(1));
  const std::vector<bytecode::LineEntry>& lines = program_->image().lines;
  const auto at_line_start = [&] {
    const auto it =
        std::lower_bound(lines.begin(), lines.end(), m.pc(task),
                         [](const bytecode::LineEntry& l, uint32_t pc) { return l.code < pc; });
    return it != lines.end() && it->code == m.pc(task);
  };
  for (uint32_t i = 0; i < kMaxGlueInstructions && !at_line_start() &&
                       (r.end == vm::SliceEnd::LineEnd || r.end == vm::SliceEnd::BudgetSpent);
       ++i)
    r = m.run_slice(task, vm::Budget::of_instructions(1));
  if (r.end == vm::SliceEnd::Error) report_error(task);
  const vm::ThreadStatus after = m.status(task);
  if (after == vm::ThreadStatus::Running || after == vm::ThreadStatus::Waiting) m.halt(task);
  return true;
}

}  // namespace uprog::pdl
