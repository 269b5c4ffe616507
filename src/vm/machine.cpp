// Loading an image into the machine's memory, and everything about threads except executing
// instructions (execute.cpp).
#include "vm/machine.h"

#include <cstring>

#include "bytecode/opcodes.h"
#include "vm/fused.h"
#include "vm/quicken.h"

namespace uprog::vm {

using bytecode::ImageView;
using bytecode::LoadError;
using bytecode::Op;

namespace {

// Carves aligned pieces out of the caller's block; counts what it would need when given none.
class Arena {
 public:
  Arena(void* memory, size_t size) : base_(static_cast<uint8_t*>(memory)), size_(size) {}

  template <typename T>
  T* take(uint64_t count) {
    used_ = (used_ + 7u) & ~uint64_t{7};
    const uint64_t bytes = count * sizeof(T);
    if (count != 0 && bytes / count != sizeof(T)) overflow_ = true;
    const uint64_t at = used_;
    used_ += bytes;
    if (overflow_ || base_ == nullptr || used_ > size_) return nullptr;
    return reinterpret_cast<T*>(base_ + at);
  }
  uint64_t used() const { return overflow_ ? UINT64_MAX : used_; }
  bool fits() const { return !overflow_ && base_ != nullptr && used_ <= size_; }

 private:
  uint8_t* base_;
  uint64_t size_;
  uint64_t used_ = 0;
  bool overflow_ = false;
};

uint64_t global_cells(const ImageView& image) {
  uint64_t cells = 0;
  for (uint32_t i = 0; i < image.globals.size(); ++i) cells += image.globals[i].length;
  return cells;
}

// What the verifier allows a program on this machine: its operand stack is the configured one.
bytecode::VerifyLimits limits_for(const MachineConfig& config) {
  bytecode::VerifyLimits limits;
  limits.max_stack = config.stack;
  return limits;
}

}  // namespace

const char* thread_status_name(ThreadStatus s) {
  switch (s) {
    case ThreadStatus::Idle:
      return "idle";
    case ThreadStatus::Running:
      return "running";
    case ThreadStatus::Waiting:
      return "waiting";
    case ThreadStatus::Halted:
      return "halted";
    case ThreadStatus::AtBreakpoint:
      return "at breakpoint";
    case ThreadStatus::Error:
      return "stopped by error";
  }
  return "unknown";
}

size_t Machine::memory_needed(const ImageView& image, const MachineConfig& config) {
  Arena a(nullptr, 0);
  a.take<uint32_t>(image.code.size());
  a.take<Value>(image.constants.size());
  a.take<RoutineInfo>(image.routines.size());
  a.take<Value*>(image.globals.size());
  a.take<uint32_t>(image.globals.size());
  a.take<Value>(global_cells(image));
  a.take<Thread>(config.threads);
  for (uint32_t t = 0; t < config.threads; ++t) {
    a.take<Value>(config.stack);
    a.take<Value>(config.locals);
    a.take<Frame>(config.frames);
    a.take<Handler>(config.handlers);
  }
  a.take<Breakpoint>(config.breakpoints);
  a.take<uint32_t>(quicken_scratch_words(image.code.size()));
  uint64_t need = a.used();
  const uint64_t scratch = bytecode::verify_scratch_size(image);
  if (scratch > need) need = scratch;
  return need > SIZE_MAX ? SIZE_MAX : static_cast<size_t>(need);
}

LoadStatus Machine::load(const uint8_t* bytes, size_t size, const MachineConfig& config,
                         void* memory, size_t memory_size, Host& host) {
  loaded_ = false;
  LoadStatus status;
  ImageView view;
  status.load = bytecode::load_image(bytes, size, view);
  if (status.load != LoadError::Ok) return status;
  if (config.threads == 0 || config.frames == 0 || config.stack == 0 ||
      memory_size < memory_needed(view, config) || memory == nullptr) {
    status.no_memory = true;
    return status;
  }
  const bytecode::VerifyResult verified =
      bytecode::verify(view, limits_for(config), memory, memory_size);
  status.verify = verified.error;
  status.pc = verified.pc;
  if (!verified.ok()) return status;

  Arena a(memory, memory_size);
  code_size_ = view.code.size();
  code_ = a.take<uint32_t>(code_size_);
  for (uint32_t i = 0; i < code_size_; ++i) code_[i] = view.code[i];
  constants_ = a.take<Value>(view.constants.size());
  for (uint32_t i = 0; i < view.constants.size(); ++i)
    constants_[i] = Value::of_bits(view.constants[i].bits);
  routine_count_ = view.routines.size();
  routines_ = a.take<RoutineInfo>(routine_count_);
  for (uint32_t i = 0; i < routine_count_; ++i) {
    const auto r = view.routines[i];
    routines_[i] = {r.entry, r.inputs, r.outputs, r.locals};
  }
  global_count_ = view.globals.size();
  global_data_ = a.take<Value*>(global_count_);
  global_length_ = a.take<uint32_t>(global_count_);
  if (global_cells(view) > UINT32_MAX) {  // more than LDM can address (and than any drive has)
    status.no_memory = true;
    return status;
  }
  memory_words_ = static_cast<uint32_t>(global_cells(view));
  Value* cells = a.take<Value>(memory_words_);
  memory_ = cells;
  for (uint32_t i = 0; i < global_count_; ++i) {
    const uint32_t length = view.globals[i].length;
    global_data_[i] = cells;
    global_length_[i] = length;
    for (uint32_t k = 0; k < length; ++k) cells[k] = Value::of_bits(0);
    cells += length;
  }
  thread_count_ = config.threads;
  threads_ = a.take<Thread>(thread_count_);
  for (uint32_t& mask : in_status_) mask = 0;
  in_status_[static_cast<uint8_t>(ThreadStatus::Idle)] =
      thread_count_ >= 32 ? ~0u : (1u << thread_count_) - 1;  // Thread{} is idle
  for (uint32_t i = 0; i < thread_count_; ++i) {
    Thread& t = threads_[i];
    t = Thread{};
    t.status_bit = i < 32 ? 1u << i : 0u;
    t.stack = a.take<Value>(config.stack);
    t.locals = a.take<Value>(config.locals);
    t.locals_end = t.locals + config.locals;
    t.frames = a.take<Frame>(config.frames);
    t.handlers = a.take<Handler>(config.handlers);
    reset_thread(t);
  }
  breakpoints_ = a.take<Breakpoint>(config.breakpoints);
  breakpoint_count_ = 0;
  uint32_t* const quicken_scratch = a.take<uint32_t>(quicken_scratch_words(code_size_));
  if (!a.fits()) {
    status.no_memory = true;
    return status;
  }
  quicken(code_, code_size_, view, quicken_scratch);
  image_ = view;
  host_ = &host;
  config_ = config;
  max_depth_ = verified.max_depth;
  loaded_ = true;
  return status;
}

bool Machine::enter(Thread& t, uint32_t routine, uint32_t return_pc, uint8_t nargout,
                    FrameKind kind, RunError& error) {
  const RoutineInfo& r = routines_[routine];
  Value* base = t.sp - r.inputs;
  if (t.frame_count >= config_.frames) {
    error = kind == FrameKind::Event ? RunError::InterruptDepth : RunError::CallDepth;
    return false;
  }
  if (static_cast<size_t>(t.locals_end - t.locals_top) < r.locals) {
    error = RunError::LocalsExhausted;
    return false;
  }
  if (static_cast<size_t>(t.stack + config_.stack - base) < max_depth_) {
    error = RunError::StackOverflow;
    return false;
  }
  push_frame(t, routine, base, return_pc, nargout, kind);
  return true;
}

// A drive's scheduler starts a routine for every run of a cyclic task (the S300's PLC62 16 000
// times a virtual second), so the checks enter() makes are made here on what they come to for a
// thread just reset: no frame, all its locals free, the stack empty but for the inputs.
RunError Machine::start(uint32_t thread, uint32_t routine, const Value* args, uint32_t arg_count) {
  if (!loaded_ || thread >= thread_count_) return RunError::NoSuchThread;
  if (routine >= routine_count_) return RunError::NoSuchRoutine;
  const RoutineInfo& r = routines_[routine];
  if (arg_count != r.inputs) return RunError::BadArguments;
  Thread& t = threads_[thread];
  // Only reset_thread() makes a thread idle: one that finished or was killed is reset already
  // (a cyclic task's next run starts here).
  if (t.status != ThreadStatus::Idle) reset_thread(t);
  const RunError refused = arg_count > config_.stack    ? RunError::StackOverflow
                           : config_.frames == 0        ? RunError::CallDepth
                           : r.locals > config_.locals  ? RunError::LocalsExhausted
                           : config_.stack < max_depth_ ? RunError::StackOverflow
                                                        : RunError::None;
  if (refused != RunError::None) return refused;  // the thread stays reset
  for (uint32_t i = 0; i < arg_count; ++i) t.stack[i] = args[i];
  set_status(t, ThreadStatus::Running);
  push_frame(t, routine, t.stack, 0, 0, FrameKind::Call);
  t.last_error = RunError::None;
  return RunError::None;
}

RunError Machine::interrupt(uint32_t thread, uint32_t routine) {
  if (!loaded_ || thread >= thread_count_) return RunError::NoSuchThread;
  if (routine >= routine_count_) return RunError::NoSuchRoutine;
  if (routines_[routine].inputs != 0) return RunError::BadArguments;
  Thread& t = threads_[thread];
  if (t.status == ThreadStatus::Error) {
    // The routine that handles a failure starts afresh, and can still read why (prgerr).
    const RunError failure = t.last_error;
    const int32_t detail = t.error_detail;
    const RunError e = start(thread, routine);
    t.last_error = failure;
    t.error_detail = detail;
    return e;
  }
  if (t.status == ThreadStatus::Idle || t.frame_count == 0) return start(thread, routine);
  RunError error = RunError::None;
  if (!enter(t, routine, t.pc, 0, FrameKind::Event, error)) return error;
  set_status(t, ThreadStatus::Running);
  return RunError::None;
}

void Machine::halt(uint32_t thread) {
  if (thread >= thread_count_) return;
  Thread& t = threads_[thread];
  if (t.status == ThreadStatus::Running || t.status == ThreadStatus::Waiting) {
    t.status_before_halt = t.status;  // a halted wait still ends at its time after resume()
    set_status(t, ThreadStatus::Halted);
  }
}

void Machine::resume(uint32_t thread) {
  if (thread >= thread_count_) return;
  Thread& t = threads_[thread];
  if (t.status == ThreadStatus::Halted) set_status(t, t.status_before_halt);
  if (t.status == ThreadStatus::AtBreakpoint) {
    set_status(t, ThreadStatus::Running);
    t.step_over = true;
  }
}

void Machine::kill(uint32_t thread) {
  if (thread < thread_count_) reset_thread(threads_[thread]);
}

RunError Machine::last_error(uint32_t thread) const {
  return thread < thread_count_ ? threads_[thread].last_error : RunError::NoSuchThread;
}
int32_t Machine::error_detail(uint32_t thread) const {
  return thread < thread_count_ ? threads_[thread].error_detail : 0;
}

FrameInfo Machine::frame(uint32_t thread, uint32_t depth) const {
  if (thread >= thread_count_ || depth >= threads_[thread].frame_count) return {0, 0, false};
  const Thread& t = threads_[thread];
  const Frame& f = t.frames[t.frame_count - 1 - depth];
  const uint32_t pc = depth == 0 ? t.pc : t.frames[t.frame_count - depth].return_pc;
  return {f.routine, pc, f.kind == FrameKind::Event};
}

bool Machine::read_global(uint32_t global, uint32_t element, Value& out) const {
  if (global >= global_count_ || element >= global_length_[global]) return false;
  out = global_data_[global][element];
  return true;
}

bool Machine::write_global(uint32_t global, uint32_t element, Value value) {
  if (global >= global_count_ || element >= global_length_[global]) return false;
  global_data_[global][element] = value;
  return true;
}

bool Machine::bind_global(uint32_t global, Value* data, uint32_t length) {
  if (global >= global_count_ || data == nullptr || length < global_length_[global]) return false;
  global_data_[global] = data;
  return true;
}

bool Machine::read_memory(uint32_t address, Value& out) const {
  if (!loaded_ || address >= memory_words_) return false;
  out = memory_[address];
  return true;
}

bool Machine::write_memory(uint32_t address, Value value) {
  if (!loaded_ || address >= memory_words_) return false;
  memory_[address] = value;
  return true;
}

bool Machine::read_local(uint32_t thread, uint32_t depth, uint32_t local, Value& out) const {
  if (thread >= thread_count_ || depth >= threads_[thread].frame_count) return false;
  const Thread& t = threads_[thread];
  const Frame& f = t.frames[t.frame_count - 1 - depth];
  if (local >= routines_[f.routine].locals) return false;
  out = f.locals[local];
  return true;
}

bool Machine::write_local(uint32_t thread, uint32_t depth, uint32_t local, Value value) {
  if (thread >= thread_count_ || depth >= threads_[thread].frame_count) return false;
  Thread& t = threads_[thread];
  const Frame& f = t.frames[t.frame_count - 1 - depth];
  if (local >= routines_[f.routine].locals) return false;
  f.locals[local] = value;
  return true;
}

std::span<const Value> Machine::operand_stack(uint32_t thread) const {
  if (thread >= thread_count_) return {};
  const Thread& t = threads_[thread];
  return {t.stack, static_cast<size_t>(t.sp - t.stack)};
}

bool Machine::move_pc(uint32_t thread, uint32_t pc, void* scratch, size_t scratch_size) {
  if (!loaded_ || thread >= thread_count_) return false;
  Thread& t = threads_[thread];
  if (t.status != ThreadStatus::Halted || t.frame_count == 0) return false;
  const Frame& f = t.frames[t.frame_count - 1];
  uint32_t depth = 0;
  if (!bytecode::stack_depth_at(image_, limits_for(config_), f.routine, pc, scratch, scratch_size,
                                depth))
    return false;
  if (static_cast<uint32_t>(t.sp - f.stack_base) != depth) return false;
  t.pc = pc;
  t.status_before_halt = ThreadStatus::Running;
  return true;
}

// The base code's instructions: a fused instruction's first word is the base one it was.
bool Machine::is_instruction_start(uint32_t pc) const {
  for (uint32_t at = 0; at < code_size_;) {
    if (at == pc) return true;
    if (at > pc) return false;
    const Breakpoint* b = find_breakpoint(at);
    const uint32_t word = base_word(b ? b->original : code_[at]);
    at += bytecode::op_length(bytecode::word_op(word));
  }
  return false;
}

// A fused instruction that `pc` lies inside is its base code again, so that a trap there is hit.
void Machine::unfuse_around(uint32_t pc) {
  for (uint32_t at = 0; at < code_size_ && at < pc;) {
    const Breakpoint* b = find_breakpoint(at);
    uint32_t& word = b ? breakpoints_[b - breakpoints_].original : code_[at];
    const uint32_t length = instruction_length(word);
    if (pc < at + length) {
      word = base_word(word);
      return;
    }
    at += length;
  }
}

const Machine::Breakpoint* Machine::find_breakpoint(uint32_t pc) const {
  for (uint32_t i = 0; i < breakpoint_count_; ++i)
    if (breakpoints_[i].pc == pc) return &breakpoints_[i];
  return nullptr;
}

bool Machine::set_breakpoint(uint32_t pc) {
  if (!loaded_ || !is_instruction_start(pc)) return false;
  if (find_breakpoint(pc)) return true;
  if (breakpoint_count_ >= config_.breakpoints) return false;
  unfuse_around(pc);
  breakpoints_[breakpoint_count_++] = {pc, code_[pc]};
  code_[pc] = bytecode::make_word(Op::BREAK, 0);
  return true;
}

bool Machine::clear_breakpoint(uint32_t pc) {
  for (uint32_t i = 0; i < breakpoint_count_; ++i) {
    if (breakpoints_[i].pc != pc) continue;
    code_[pc] = breakpoints_[i].original;
    breakpoints_[i] = breakpoints_[--breakpoint_count_];
    return true;
  }
  return false;
}

bool Machine::raise(Thread& t, RunError error, int32_t detail) {
  t.last_error = error;
  t.error_detail = detail;
  if (t.handler_count > 0) {
    const Handler& h = t.handlers[t.handler_count - 1];
    // A TRY block does not catch errors of an event routine entered on top of it; TRYALL does.
    bool event_between = false;
    for (uint32_t i = h.frame_count; i < t.frame_count && !h.catches_events; ++i)
      event_between = event_between || t.frames[i].kind == FrameKind::Event;
    if (!event_between) {
      t.handler_count--;
      t.frame_count = h.frame_count;
      t.sp = h.sp;
      t.locals_top = h.locals_top;
      t.pc = h.catch_pc;
      return true;
    }
  }
  set_status(t, ThreadStatus::Error);
  return false;
}

}  // namespace uprog::vm
