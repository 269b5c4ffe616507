// What the Gold firmware offers the debugger (dialect::Firmware's debug hooks): an expression in
// Gold's syntax evaluated in a frame of the program (breakpoint conditions, watches, hovers), and
// a start with arguments.
#include <algorithm>

#include "dialects/gold/firmware.h"
#include "dialects/gold/number_format.h"
#include "vm/run_error.h"

namespace uprog::gold {
namespace {

// A watch is an expression; a small budget ends a runaway one with an error.
constexpr uint64_t kEvaluationInstructionBudget = 100'000;

vm::MachineConfig evaluation_config() {
  vm::MachineConfig c;
  c.threads = 1;
  c.locals = 64;
  c.breakpoints = 0;
  return c;
}

// The frame's locals seen as globals after the program's own: the line compiler knows globals
// only. A local hides a global of its name, as in the function's body.
std::vector<KnownGlobal> names_in_scope(std::vector<KnownGlobal> globals,
                                        const bytecode::Routine* routine) {
  if (routine == nullptr) return globals;
  for (const bytecode::Local& l : routine->locals) {
    for (KnownGlobal& g : globals)
      if (g.name == l.name) g.name.insert(0, "\x01");  // no expression can name it any more
    KnownGlobal k;
    k.name = l.name;
    k.type = l.type == ValueType::Int ? VarType::Int : VarType::Float;
    globals.push_back(std::move(k));
  }
  return globals;
}

}  // namespace

dialect::Evaluation Firmware::evaluate(uint32_t thread, uint32_t depth,
                                       std::string_view expression) {
  dialect::Evaluation out;
  if (!program_) {
    out.error = "no program is loaded";
    return out;
  }
  vm::Machine& pm = program_->machine();
  const bytecode::Routine* routine = nullptr;
  if (depth < pm.frame_count(thread))
    routine = &program_->image().routines[pm.frame(thread, depth).routine];
  const std::vector<KnownGlobal> known = names_in_scope(known_globals_, routine);
  const CompiledLine line = compile_line(expression, known);
  if (!line.ok()) {
    out.error = line.diagnostics.empty() ? "syntax error" : line.diagnostics.front().message;
    return out;
  }
  std::string why;
  const auto loaded = dialect::LoadedProgram::load(bytecode::encode(line.image),
                                                   evaluation_config(), *this, &why, false);
  if (!loaded) {
    out.error = "the expression's image is unsound: " + why;
    return out;
  }
  vm::Machine& m = loaded->machine();
  const uint32_t shared = static_cast<uint32_t>(known_globals_.size());
  const uint32_t local_count = routine ? static_cast<uint32_t>(routine->locals.size()) : 0;
  // The globals are the program's own words (bound); the frame's locals are copied in, and out
  // again afterwards, since a watch may assign.
  bind_program_globals(m);
  auto exchange = [&](bool into_line) {
    for (uint32_t l = 0; l < local_count; ++l) {
      Value v;
      if (into_line ? pm.read_local(thread, depth, l, v) : m.read_global(shared + l, 0, v)) {
        into_line ? m.write_global(shared + l, 0, v) : pm.write_local(thread, depth, l, v);
      }
    }
  };
  exchange(true);
  const uint32_t generation = program_generation_;
  const vm::SliceResult r = run_bound(m, kEvaluationInstructionBudget);
  if (r.end != vm::SliceEnd::Finished) {
    out.error = r.end == vm::SliceEnd::Error ? vm::run_error_text(m.last_error(0))
                                             : "the expression did not finish";
    return out;
  }
  if (generation == program_generation_) exchange(false);  // else `pm` was another program's
  out.ok = true;
  for (const LineValue& v : line.values) {
    Value value;
    m.read_global(v.value_global, 0, value);
    bool is_float = v.kind == Kind::Float;
    if (v.kind == Kind::Dynamic && v.tag_global >= 0) {
      Value tag;
      m.read_global(static_cast<uint32_t>(v.tag_global), 0, tag);
      is_float = tag.i == 1;
    }
    if (!out.value.empty()) out.value += ", ";
    out.value += is_float ? format_gold_float(value.f) : format_gold_int(value.i);
    out.is_true = is_float ? value.f != 0.0f : value.i != 0;
  }
  return out;
}

std::string Firmware::start_with_arguments(std::string_view entry,
                                           const std::vector<double>& args) {
  if (args.empty()) return start(entry);
  std::string error;
  if (load_stored(&error) != 0) return error;
  const std::string name = entry.empty() ? "main" : std::string(entry);
  const int32_t code = execute_program(name, args);
  return code == 0 ? std::string()
                   : "cannot start at '" + name + "' (error " + std::to_string(code) + ")";
}

}  // namespace uprog::gold
