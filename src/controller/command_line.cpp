// The Gold command line: a host line split into expressions, each compiled with
// gold::compile_line into a tiny image and run to its end on a machine of its own, which sees
// the loaded program's globals (copied in before, and back after).
#include <algorithm>

#include "controller/controller_impl.h"
#include "controller/line_splitter.h"
#include "controller/number_format.h"
#include "vm/run_error.h"

namespace uprog::controller {
namespace {

// A command line is one statement list; it may not wait, so a small budget is plenty and a
// runaway line (a loop typed at the prompt) ends with an error instead of hanging the drive.
constexpr uint64_t kLineInstructionBudget = 1'000'000;

vm::MachineConfig line_config() {
  vm::MachineConfig c;
  c.threads = 1;
  c.locals = 64;
  c.breakpoints = 0;
  return c;
}

}  // namespace

Answer Controller::Impl::error_answer(int32_t code, std::string why) {
  ec = code;
  return Answer{"Error: " + why, code};
}

std::vector<Answer> Controller::Impl::send(std::string_view text, bool takes_time) {
  std::vector<Answer> answers;
  for (const std::string& e : split_expressions(text)) {
    expression(e, answers);
    // The drive answers from its background loop: every expression takes one servo cycle.
    if (takes_time) advance(axis->period_us());
  }
  return answers;
}

void Controller::Impl::expression(const std::string& text, std::vector<Answer>& answers) {
  if (text.size() > kMaxExpressionChars) {
    answers.push_back(error_answer(kErrorSyntax, "Command syntax error: the expression is longer than " +
                                                     std::to_string(kMaxExpressionChars) + " characters"));
    return;
  }
  if (program_control(text, answers)) return;
  run_line(text, answers);
}

void Controller::Impl::run_line(const std::string& text, std::vector<Answer>& answers) {
  const gold::CompiledLine line = gold::compile_line(text, known_globals);
  if (!line.ok()) {
    std::string why = "Command syntax error";
    if (!line.diagnostics.empty()) {
      const Diagnostic& d = line.diagnostics.front();
      why += ": " + d.message + " [gold " + std::to_string(d.code) + "]";
    }
    answers.push_back(error_answer(kErrorSyntax, why));
    return;
  }
  const std::vector<uint8_t> bytes = bytecode::encode(line.image);
  bytecode::ImageView view;
  if (bytecode::load_image(bytes.data(), bytes.size(), view) != bytecode::LoadError::Ok) {
    answers.push_back(error_answer(kErrorSyntax, "Command syntax error: the line's image is unsound"));
    return;
  }
  const vm::MachineConfig config = line_config();
  std::vector<uint64_t> memory((vm::Machine::memory_needed(view, config) + 7) / 8);
  vm::Machine m;
  if (!m.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, *this).ok()) {
    answers.push_back(error_answer(kErrorSyntax, "Command syntax error: the line does not verify"));
    return;
  }
  // The program's globals come first in the line's image, in the same order.
  const uint32_t shared = static_cast<uint32_t>(known_globals.size());
  auto copy_globals = [&](const vm::Machine& from, vm::Machine& to) {
    for (uint32_t g = 0; g < shared; ++g) {
      const uint32_t length = std::max<int32_t>(known_globals[g].length, 1);
      for (uint32_t i = 0; i < length; ++i) {
        Value v;
        if (from.read_global(g, i, v)) to.write_global(g, i, v);
      }
    }
  };
  const uint32_t generation = program_generation;
  if (machine) copy_globals(*machine, m);
  m.start(0, 0);
  const vm::SliceResult r = m.run_slice(0, vm::Budget::of_instructions(kLineInstructionBudget));
  // Whatever the line assigned before it ended stays assigned, unless the program was replaced.
  if (machine && generation == program_generation) copy_globals(m, *machine);
  if (r.end == vm::SliceEnd::Error) {
    const vm::RunError e = m.last_error(0);
    if (e == vm::RunError::CommandRefused) {
      answers.push_back(error_answer(m.error_detail(0), "drive error " + std::to_string(m.error_detail(0))));
    } else {
      answers.push_back(error_answer(kErrorRunTimeBase + static_cast<int32_t>(e), vm::run_error_text(e)));
    }
    return;
  }
  if (r.end != vm::SliceEnd::Finished) {
    answers.push_back(error_answer(kErrorLineDidNotFinish, "the line did not finish (it waited or ran too long)"));
    return;
  }
  for (const gold::LineValue& v : line.values) {
    Value value;
    m.read_global(v.value_global, 0, value);
    bool is_float = v.kind == gold::Kind::Float;
    if (v.kind == gold::Kind::Dynamic && v.tag_global >= 0) {
      Value tag;
      m.read_global(static_cast<uint32_t>(v.tag_global), 0, tag);
      is_float = tag.i == 1;
    }
    answers.push_back(Answer{is_float ? format_gold_float(value.f) : format_gold_int(value.i), 0});
  }
}

}  // namespace uprog::controller
