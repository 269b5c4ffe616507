// What the S300 firmware offers the debugger (dialect::Firmware's debug hooks): the program in
// RAM, and an ST expression or assignment evaluated against the program's globals (breakpoint
// conditions, watches, hovers), compiled by the drive's own compiler.
#include <fmt/core.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dialects/st/firmware.h"
#include "dialects/st/names.h"
#include "vm/run_error.h"

namespace uprog::st {
namespace {

// The expression is compiled with the stored source, as a function of its own that no program
// calls, storing into a global declared after the program's (so the program's globals keep their
// places). Names a program is unlikely to use; one that does gets "declared twice".
constexpr std::string_view kResult = "ZQDBGVAL";
constexpr std::string_view kFunction = "ZQDBGFN";
constexpr uint64_t kEvaluationInstructionBudget = 100'000;  // ends a runaway expression

vm::MachineConfig evaluation_config() {
  vm::MachineConfig c;
  c.threads = 1;
  c.stack = 512;
  c.breakpoints = 0;
  return c;
}

// `NAME := expression` is an assignment that stays made; anything else is an expression.
std::optional<std::string> assigned_name(std::string_view text) {
  const size_t at = text.find(":=");
  if (at == std::string_view::npos) return std::nullopt;
  std::string name(text.substr(0, at));
  while (!name.empty() && name.back() == ' ') name.pop_back();
  while (!name.empty() && name.front() == ' ') name.erase(name.begin());
  return name;
}

std::string evaluation_source(const std::string& source, std::string_view expression) {
  std::string body;
  if (auto name = assigned_name(expression)) {
    body = fmt::format("  {};\n  {} := {};\n", expression, kResult, *name);
  } else {
    body = fmt::format("  {} := {};\n", kResult, expression);
  }
  return fmt::format("{}\nLONG {};\nFUNCTION {}\n{}END_FUNCTION\n", source, kResult, kFunction,
                     body);
}

}  // namespace

void Firmware::set_debug_map(std::string_view map) {
  const nlohmann::json j = nlohmann::json::parse(map, nullptr, false);
  if (!source_ || !j.is_object() || !j.contains("source") || !j["source"].is_string()) {
    runtime_.log("debug map refused: not an ST debug map");
    return;
  }
  source_name_ = j["source"].get<std::string>();
  named_source_ = *source_;
}

dialect::Evaluation Firmware::evaluate(uint32_t, uint32_t, std::string_view expression) {
  dialect::Evaluation out;
  if (!program_ || !source_) {
    out.error = "no program is loaded";
    return out;
  }
  // One expression or assignment: a statement list could call the built-ins that print or
  // command the drive, whose texts live in the evaluator's image, not the program's.
  if (expression.find_first_of(";\r\n") != std::string_view::npos) {
    out.error = "one expression or assignment, without ';'";
    return out;
  }
  vm::Machine& pm = program_->machine();
  // A variable alone is read as the command line reads it (a DLONG as one 64-bit number).
  std::string trimmed(expression);
  while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
  while (!trimmed.empty() && trimmed.front() == ' ') trimmed.erase(trimmed.begin());
  if (const int g = program_->image().find_global(trimmed); g >= 0) {
    const bytecode::Global& global = program_->image().globals[static_cast<size_t>(g)];
    Value low, high;
    pm.read_global(static_cast<uint32_t>(g), 0, low);
    int64_t v = low.i;
    if (global.length == 2 && pm.read_global(static_cast<uint32_t>(g), 1, high))
      v = static_cast<int64_t>((static_cast<uint64_t>(static_cast<uint32_t>(high.i)) << 32) |
                               static_cast<uint32_t>(low.i));
    out.ok = true;
    out.value = std::to_string(v);
    out.is_true = v != 0;
    return out;
  }
  CompileOptions options;
  options.parameter = [this](std::string_view name) { return parameter_value(name); };
  const CompileResult r =
      compile(SourceFile{source_name(), evaluation_source(*source_, trimmed)}, options);
  if (!r.ok()) {
    out.error = r.diagnostics.empty() ? "syntax error" : r.diagnostics.back().message;
    return out;
  }
  const int fn = r.image.find_routine(std::string(kFunction));
  const int result = r.image.find_global(std::string(kResult));
  if (fn < 0 || result < 0 || r.image.globals.size() != globals_.size() + 1) {
    out.error = "the expression does not compile with this program";
    return out;
  }
  std::string why;
  const auto loaded = dialect::LoadedProgram::load(bytecode::encode(r.image), evaluation_config(),
                                                   *this, &why, false);
  if (!loaded) {
    out.error = "the expression's image is unsound: " + why;
    return out;
  }
  vm::Machine& m = loaded->machine();
  // The program's globals in, and out again afterwards: an assignment stays made.
  const auto exchange = [&](vm::Machine& from, vm::Machine& to) {
    for (uint32_t g = 0; g < globals_.size(); ++g) {
      for (uint32_t i = 0; i < std::max<uint32_t>(globals_[g].length, 1); ++i) {
        Value v;
        if (from.read_global(g, i, v)) to.write_global(g, i, v);
      }
    }
  };
  exchange(pm, m);
  m.start(0, static_cast<uint32_t>(fn));
  vm::SliceResult s{vm::SliceEnd::Yielded, 0};
  uint64_t left = kEvaluationInstructionBudget;
  // A costly built-in (XREAD …) ends a slice; the evaluation takes no virtual time all the same.
  while (s.end == vm::SliceEnd::Yielded && left > 0) {
    s = m.run_slice(0, vm::Budget::of_instructions(left));
    left -= std::min(left, std::max<uint64_t>(s.executed, 1));
  }
  if (s.end != vm::SliceEnd::Finished) {
    out.error = s.end == vm::SliceEnd::Error ? vm::run_error_text(m.last_error(0))
                                             : "the expression did not finish";
    return out;
  }
  exchange(m, pm);
  Value v;
  m.read_global(static_cast<uint32_t>(result), 0, v);
  out.ok = true;
  out.value = std::to_string(v.i);
  out.is_true = v.i != 0;
  return out;
}

}  // namespace uprog::st
