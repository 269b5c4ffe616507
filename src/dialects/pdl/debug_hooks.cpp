// What the D-series firmware offers the debugger (dialect::Firmware's debug hooks): the program
// in RAM; each task's frames, walked from its VM frames (a procedure's routine each) and the
// words of its stack in the data memory (loop counts, the return ids of `call`s, the procedures'
// parameters and locals) with the image's debug info (debug_info.h); and PDL expressions,
// conditions and assignments compiled by the drive's own compiler (compile_evaluation) and run
// on a scratch machine over a copy of the data memory.
#include <fmt/core.h>

#include <algorithm>

#include "dialects/pdl/compile.h"
#include "dialects/pdl/firmware.h"
#include "vm/run_error.h"

namespace uprog::pdl {
namespace {

constexpr uint64_t kEvaluationInstructionBudget = 100'000;  // ends a runaway expression
constexpr uint32_t kMaxFrames = kStackWords;  // every frame takes a stack word at least

vm::MachineConfig evaluation_config() {
  vm::MachineConfig c;
  c.threads = 1;
  c.locals = kEntryLocals;
  c.breakpoints = 0;
  return c;
}

std::string show(Value v, bool is_float) {
  if (!is_float) return std::to_string(v.i);
  std::string s = fmt::format("{}", v.f);
  if (s.find_first_of(".ein") == std::string::npos) s += ".0";
  return s;
}

std::string type_of(const FrameVar& v) {
  std::string t = v.kind == 'f' ? "float" : v.kind == 's' ? "short" : "long";
  if (v.pointer) t += "*";
  if (v.length > 1) t += "[" + std::to_string(v.length) + "]";
  return t;
}

}  // namespace

// From the innermost out, VM frame by VM frame: a procedure's routine has its frame at fp
// (2 reserved words, parameters, locals), task code the stack's base; above that stand the counts
// of the loops open at pc, then, if anything is left, the return id of a `call` to a label, which
// is a frame too. A word that does not fit (a goto out of a loop leaves its count behind) ends
// the walk there.
std::vector<Firmware::TaskFrame> Firmware::walk_frames(uint32_t task) const {
  std::vector<TaskFrame> out;
  const vm::Machine* m = machine();
  if (m == nullptr || task < 1 || task > kTasks || m->frame_count(task) == 0) return out;
  const vm::ThreadStatus s = m->status(task);
  if (s == vm::ThreadStatus::Idle) return out;
  const int32_t base = stack_base(task), limit = base + kStackWords;
  for (uint32_t depth = 0; depth < m->frame_count(task) && out.size() < kMaxFrames; ++depth) {
    Value reg;
    auto local = [&](uint32_t i) { return m->read_local(task, depth, i, reg) ? reg.i : 0; };
    // A caller resumes after its CALL, whose last word is still on the calling line.
    const uint32_t pc = depth == 0 ? m->pc(task) : m->frame(task, depth).pc;
    const uint32_t line_pc = depth == 0 || pc == 0 ? pc : pc - 1;
    const ProcInfo* proc = debug_info_.proc_at(pc);
    if (!walk_routine_frame(pc, line_pc, local(kSp), local(kFp), base, limit, out)) break;
    if (proc == nullptr) break;  // task code is the outermost
  }
  return out;
}

// One VM frame's frames: its own, then the `call`s to labels inside it. False when a word did
// not fit (the walk ends).
bool Firmware::walk_routine_frame(uint32_t pc, uint32_t line_pc, int32_t sp, int32_t fp,
                                  int32_t base, int32_t limit, std::vector<TaskFrame>& out) const {
  const vm::Machine* m = machine();
  while (out.size() < kMaxFrames) {
    const ProcInfo* proc = debug_info_.proc_at(pc);
    out.push_back({proc, line_pc, fp});
    if (sp < base || sp > limit || (proc && (fp < base || fp + proc->frame_words > limit)))
      return false;
    const int32_t bottom = proc ? fp + proc->frame_words : base;
    const int32_t above = sp - static_cast<int32_t>(debug_info_.loops_open(pc));
    if (above == bottom) return true;
    Value id;
    if (above < bottom || !m->read_memory(static_cast<uint32_t>(above - 1), id) || id.i < 0 ||
        static_cast<size_t>(id.i) >= debug_info_.return_sites.size())
      return false;
    pc = debug_info_.return_sites[static_cast<size_t>(id.i)];
    line_pc = pc == 0 ? 0 : pc - 1;  // the call's last word, on the calling line
    sp = above - 1;
  }
  return false;
}

std::string Firmware::frame_name(const TaskFrame& f) const {
  if (f.proc) return f.proc->name;
  // Task code: the label (or #task place) it is in, the nearest entry at or before it.
  const bytecode::Image& image = program_->image();
  const bytecode::Routine* best = nullptr;
  for (const bytecode::Routine& r : image.routines) {
    if (r.entry > f.pc || debug_info_.proc_at(r.entry) != nullptr) continue;
    if (best == nullptr || r.entry >= best->entry) best = &r;
  }
  return best ? best->name : "(start)";
}

std::optional<std::vector<dialect::DebugFrame>> Firmware::debug_frames(uint32_t thread) {
  std::vector<dialect::DebugFrame> out;
  if (!program_) return out;
  for (const TaskFrame& f : walk_frames(thread)) {
    dialect::DebugFrame d{frame_name(f), f.pc, {}};
    if (f.proc) {
      for (const FrameVar& v : f.proc->vars) {
        std::string value;
        for (uint32_t i = 0; i < v.length; ++i) {
          Value w;
          if (!machine()->read_memory(static_cast<uint32_t>(f.fp + v.offset) + i, w)) break;
          value += (i == 0 ? "" : ", ") + show(w, v.kind == 'f' && !v.pointer);
        }
        if (v.length > 1) value = "[" + value + "]";
        d.locals.push_back({v.name, value, type_of(v)});
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

std::optional<uint32_t> Firmware::debug_call_depth(uint32_t thread) {
  return static_cast<uint32_t>(walk_frames(thread).size());
}

// A procedure's first command, past the prologue that builds its frame (which has no line).
std::optional<uint32_t> Firmware::debug_function_entry(std::string_view name) {
  if (!program_) return std::nullopt;
  for (const ProcInfo& p : debug_info_.procs) {
    if (p.name != name) continue;
    for (const bytecode::LineEntry& e : program_->image().lines)
      if (e.code >= p.first && e.code < p.end) return e.code;
  }
  return std::nullopt;
}

dialect::Evaluation Firmware::evaluate(uint32_t thread, uint32_t depth,
                                       std::string_view expression) {
  dialect::Evaluation out;
  if (!program_) {
    out.error = "no program is loaded";
    return out;
  }
  // The frame's procedure and stack registers; in task code, or with no task, none.
  const std::vector<TaskFrame> frames = walk_frames(thread);
  const TaskFrame* frame = depth < frames.size() ? &frames[depth] : nullptr;
  const EvaluationCode code =
      compile_evaluation(expression, program_->image(), frame ? frame->proc : nullptr);
  if (!code.ok) {
    out.error = code.error;
    return out;
  }
  std::string why;
  const auto loaded = dialect::LoadedProgram::load(bytecode::encode(code.image),
                                                   evaluation_config(), *this, &why, false);
  if (!loaded) {
    out.error = "the expression's image is unsound: " + why;
    return out;
  }
  vm::Machine& pm = *machine();
  vm::Machine& em = loaded->machine();
  const auto copy = [](const vm::Machine& from, vm::Machine& to) {
    for (uint32_t a = 0; a < static_cast<uint32_t>(kMemoryWords); ++a) {
      Value v;
      if (from.read_memory(a, v)) to.write_memory(a, v);
    }
  };
  copy(pm, em);
  const uint32_t task = thread >= 1 && thread <= kTasks ? thread : 1;
  const int32_t base = stack_base(task);
  Value sp = Value::of_int(base);
  if (pm.frame_count(task) > 0) pm.read_local(task, 0, kSp, sp);
  const auto args = stack_registers(task, sp, frame ? frame->fp : base);
  em.start(0, 0, args.data(), kEntryInputs);
  vm::SliceResult s{vm::SliceEnd::Yielded, 0};
  uint64_t left = kEvaluationInstructionBudget;
  // A command's end or a host call ends a slice; the evaluation takes no virtual time all the same.
  while ((s.end == vm::SliceEnd::Yielded || s.end == vm::SliceEnd::BudgetSpent) && left > 0) {
    s = em.run_slice(0, vm::Budget::of_instructions(left));
    left -= std::min(left, std::max<uint64_t>(s.executed, 1));
  }
  if (s.end != vm::SliceEnd::Finished) {
    out.error = s.end == vm::SliceEnd::Error ? vm::run_error_text(em.last_error(0))
                                             : "the expression did not finish";
    return out;
  }
  copy(em, pm);  // an assignment stays made
  Value v;
  em.read_global(static_cast<uint32_t>(code.image.globals.size() - 1), 0, v);
  out.ok = true;
  out.value = show(v, code.is_float);
  out.is_true = code.is_float ? v.f != 0.0f : v.i != 0;
  return out;
}

dialect::Evaluation Firmware::set_debug_local(uint32_t thread, uint32_t depth,
                                              std::string_view name, std::string_view value) {
  const std::vector<TaskFrame> frames = walk_frames(thread);
  if (depth >= frames.size() || frames[depth].proc == nullptr)
    return {false, {}, false, "this frame has no locals"};
  const auto& vars = frames[depth].proc->vars;
  if (std::none_of(vars.begin(), vars.end(), [&](const FrameVar& v) { return v.name == name; }))
    return {false, {}, false, "no local named '" + std::string(name) + "'"};
  return evaluate(thread, depth, "set " + std::string(name) + " = " + std::string(value));
}

}  // namespace uprog::pdl
