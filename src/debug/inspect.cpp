// What the debugger shows of a stopped program (debugger.h): threads, call stacks with each
// frame's locals, globals, the drive's signals; setting a variable; evaluating an expression.
#include <fmt/core.h>

#include "debug/debugger.h"
#include "debug/values.h"
#include "drive/axis.h"

namespace uprog::debug {
namespace {

// What a compiler adds for itself ("$t0", Gold's "$tag1", PDL's "(stack 1)"): no dialect's name
// starts so, and a user debugging the program never declared it.
bool compiler_made(std::string_view name) {
  return !name.empty() && (name.front() == '$' || name.front() == '(');
}

const char* type_name(ValueType t) { return t == ValueType::Int ? "int" : "float"; }

}  // namespace

std::vector<dialect::ThreadInfo> Debugger::threads() const { return drive_.firmware().threads(); }

std::vector<StackFrame> Debugger::stack(uint32_t thread) const {
  std::vector<StackFrame> out;
  const dialect::LoadedProgram* p = program();
  if (p == nullptr) return out;
  const vm::Machine& m = p->machine();
  const bytecode::Image& image = p->image();
  if (const auto frames = drive_.firmware().debug_frames(thread)) {
    // The dialect's own frames (PDL's procedures): each names the code word of its line.
    for (uint32_t depth = 0; depth < frames->size(); ++depth) {
      const dialect::DebugFrame& f = (*frames)[depth];
      StackFrame s;
      s.depth = depth;
      s.routine = f.routine;
      s.pc = f.pc;
      if (const bytecode::LineEntry* e = image.line_at(f.pc)) {
        s.file = e->file;
        s.line = e->line;
      }
      out.push_back(std::move(s));
    }
    return out;
  }
  for (uint32_t depth = 0; depth < m.frame_count(thread); ++depth) {
    const vm::FrameInfo f = m.frame(thread, depth);
    StackFrame s;
    s.depth = depth;
    s.routine = f.routine < image.routines.size() ? image.routines[f.routine].name : "?";
    s.pc = f.pc;
    s.is_event = f.is_event;
    // A caller resumes after its call instruction, whose last word is still the calling line.
    const uint32_t at = depth == 0 || f.pc == 0 ? f.pc : f.pc - 1;
    if (const bytecode::LineEntry* e = image.line_at(at)) {
      s.file = e->file;
      s.line = e->line;
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Variable> Debugger::locals(uint32_t thread, uint32_t depth) const {
  std::vector<Variable> out;
  const dialect::LoadedProgram* p = program();
  if (p == nullptr) return out;
  if (const auto frames = drive_.firmware().debug_frames(thread)) {
    if (depth < frames->size())
      for (const dialect::DebugVariable& v : (*frames)[depth].locals)
        out.push_back({v.name, v.value, v.type, 0});
    return out;
  }
  if (depth >= p->machine().frame_count(thread)) return out;
  const vm::Machine& m = p->machine();
  const bytecode::Routine& r = p->image().routines[m.frame(thread, depth).routine];
  for (uint32_t i = 0; i < r.locals.size(); ++i) {
    Value v;
    if (compiler_made(r.locals[i].name) || !m.read_local(thread, depth, i, v)) continue;
    out.push_back(
        {r.locals[i].name, show_value(v, r.locals[i].type), type_name(r.locals[i].type), 0});
  }
  return out;
}

std::vector<Variable> Debugger::globals() const {
  std::vector<Variable> out;
  const dialect::LoadedProgram* p = program();
  if (p == nullptr) return out;
  const std::vector<bytecode::Global>& gs = p->image().globals;
  for (uint32_t g = 0; g < gs.size(); ++g) {
    if (compiler_made(gs[g].name)) continue;
    Variable var{gs[g].name, {}, type_name(gs[g].type), 0};
    if (gs[g].length > 1) {
      var.elements = gs[g].length;
      var.value = fmt::format("{}[{}]", type_name(gs[g].type), gs[g].length);
    } else if (Value v; p->machine().read_global(g, 0, v)) {
      var.value = show_value(v, gs[g].type);
    }
    out.push_back(std::move(var));
  }
  // What the dialect keeps beyond the image (PUP's variables in AGenData).
  for (const dialect::DebugVariable& v : drive_.firmware().debug_variables())
    out.push_back({v.name, v.value, v.type, 0});
  return out;
}

std::vector<Variable> Debugger::elements(uint32_t global) const {
  std::vector<Variable> out;
  const dialect::LoadedProgram* p = program();
  if (p == nullptr || global >= p->image().globals.size()) return out;
  const bytecode::Global& g = p->image().globals[global];
  for (uint32_t i = 0; i < g.length; ++i) {
    Value v;
    if (p->machine().read_global(global, i, v)) {
      out.push_back({fmt::format("[{}]", i), show_value(v, g.type), type_name(g.type), 0});
    }
  }
  return out;
}

std::vector<Variable> Debugger::signals() const {
  drive::Axis& a = drive_.axis();
  auto number = [](auto v) { return fmt::format("{}", v); };
  return {
      {"position", number(a.position()), "counts", 0},
      {"velocity", number(a.velocity()), "counts/s", 0},
      {"position error", number(a.position_error()), "counts", 0},
      {"reference position", number(a.reference_position()), "counts", 0},
      {"motor on", a.motor_on() ? "1" : "0", "bool", 0},
      {"motion status", number(a.motion_status()), "0 settled, 1 stationary, 2 moving, 3 off", 0},
      {"status register", fmt::format("0x{:08X}", a.status_register()), "bits", 0},
      {"motor fault", fmt::format("0x{:08X}", a.motor_fault()), "bits", 0},
      {"input port", fmt::format("0x{:08X}", a.input_port()), "bits", 0},
      {"output port", fmt::format("0x{:08X}", a.output_port()), "bits", 0},
      {"virtual time", number(drive_.now_us()), "us", 0},
  };
}

int Debugger::find_global(const std::string& name) const {
  const dialect::LoadedProgram* p = program();
  return p == nullptr ? -1 : p->image().find_global(name);
}

SetResult Debugger::set_local(uint32_t thread, uint32_t depth, const std::string& name,
                              const std::string& text) {
  SetResult out;
  dialect::LoadedProgram* p = program();
  if (p != nullptr && drive_.firmware().debug_frames(thread)) {
    const dialect::Evaluation e = drive_.firmware().set_debug_local(thread, depth, name, text);
    return {e.ok, e.value, e.error};
  }
  if (p == nullptr || depth >= p->machine().frame_count(thread)) {
    out.error = "no such frame";
    return out;
  }
  vm::Machine& m = p->machine();
  const bytecode::Routine& r = p->image().routines[m.frame(thread, depth).routine];
  for (uint32_t i = 0; i < r.locals.size(); ++i) {
    if (r.locals[i].name != name) continue;
    const auto v = parse_value(text, r.locals[i].type);
    if (!v) {
      out.error =
          "'" + text + "' is not " + (r.locals[i].type == ValueType::Int ? "an int" : "a float");
      return out;
    }
    m.write_local(thread, depth, i, *v);
    return {true, show_value(*v, r.locals[i].type), {}};
  }
  out.error = "no local named '" + name + "'";
  return out;
}

SetResult Debugger::set_global(uint32_t global, uint32_t element, const std::string& text) {
  SetResult out;
  dialect::LoadedProgram* p = program();
  if (p == nullptr || global >= p->image().globals.size()) {
    out.error = "no such global";
    return out;
  }
  const ValueType type = p->image().globals[global].type;
  const auto v = parse_value(text, type);
  if (!v) {
    out.error = "'" + text + "' is not " + (type == ValueType::Int ? "an int" : "a float");
    return out;
  }
  if (!p->machine().write_global(global, element, *v)) {
    out.error = "no element " + std::to_string(element);
    return out;
  }
  return {true, show_value(*v, type), {}};
}

dialect::Evaluation Debugger::evaluate(uint32_t thread, uint32_t depth,
                                       const std::string& expression) {
  dialect::Evaluation e = drive_.firmware().evaluate(thread, depth, expression);
  if (e.ok || program() == nullptr) return e;
  // Without the dialect's evaluator (or where it refused), a variable's name still answers.
  for (const std::vector<Variable>& scope : {locals(thread, depth), globals()}) {
    for (const Variable& v : scope) {
      if (v.name == expression && v.elements == 0)
        return {true, v.value, v.value != "0" && v.value != "0.0", {}};
    }
  }
  return e;
}

}  // namespace uprog::debug
