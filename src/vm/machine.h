// The uprog virtual machine: threads running a verified image in slices, with event entry,
// try/catch, waits, breakpoints and drive commands through the Host. Freestanding: all memory
// comes from one block the caller gives to load(); nothing is allocated afterwards.
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "bytecode/image_view.h"
#include "bytecode/opcodes.h"
#include "bytecode/verifier.h"
#include "support/value.h"
#include "vm/host.h"
#include "vm/run_error.h"

namespace uprog::vm {

enum class ThreadStatus : uint8_t { Idle, Running, Waiting, Halted, AtBreakpoint, Error };
const char* thread_status_name(ThreadStatus s);

struct MachineConfig {
  uint32_t threads = 4;
  uint32_t stack = 50;     // expression stack entries per thread
  uint32_t frames = 30;    // call stack frames per thread (event entries count too)
  uint32_t locals = 1024;  // local variable slots per thread, all frames together
  uint32_t handlers = 8;   // nested try blocks per thread
  uint32_t breakpoints = 16;
};

// How much a slice may run: it stops when any count is spent (0 = no limit for that count).
// back_jumps counts jumps to an earlier place, calls, caught errors and restarts (RESET): every
// loop takes one per iteration, so it bounds a slice even in code that never ends a line (a
// hand-made image's `L: JMP L`, or its call tree of routines each calling the next twice) at
// no cost per instruction.
struct Budget {
  uint64_t instructions = 0;
  uint64_t lines = 0;
  uint64_t back_jumps = 0;
  static Budget unlimited() { return {}; }
  static Budget of_instructions(uint64_t n) { return {n, 0, 0}; }
  static Budget of_lines(uint64_t n) { return {0, n, 0}; }
};

enum class SliceEnd : uint8_t {
  BudgetSpent,  // the instruction or back-jump budget ran out
  LineEnd,      // the line budget ran out at an end-of-line
  Yielded,      // the program asked to end the slice (a condition wait)
  Waiting,      // a timed wait has not elapsed
  Finished,     // the program ended (return from its outermost routine, or exit)
  Halted,       // halted by the host; resume() continues it
  Breakpoint,   // stopped at a breakpoint
  Error,        // stopped by a run-time error that no try block caught
  NotRunning,   // the thread was idle
};

// The threads of a round (Machine::run_round), which take their turns in ascending order, and
// how far it went.
struct Round {
  uint32_t threads = 0;  // thread n is bit n
  uint32_t at = 0;       // the thread running, or the last one run or looked at
};

struct SliceResult {
  SliceEnd end;
  uint64_t executed;   // instructions run in this slice; counted only under an instruction budget
  uint64_t lines = 0;  // line ends passed in this slice; counted only under a line budget
};

struct LoadStatus {
  bytecode::LoadError load = bytecode::LoadError::Ok;
  bytecode::VerifyError verify = bytecode::VerifyError::Ok;
  uint32_t pc = 0;  // where the verifier objected
  bool no_memory = false;
  bool ok() const {
    return load == bytecode::LoadError::Ok && verify == bytecode::VerifyError::Ok && !no_memory;
  }
};

struct FrameInfo {
  uint32_t routine;
  uint32_t pc;    // where this frame is now (the innermost) or will resume (callers)
  bool is_event;  // entered by interrupt(), not by a call
};

class Machine {
 public:
  Machine() = default;
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  // The memory load() needs for this image and configuration, in bytes.
  static size_t memory_needed(const bytecode::ImageView& image, const MachineConfig& config);

  // Checks, verifies and takes the image; `image` and `memory` must outlive the machine.
  // `memory` must be aligned for 8-byte values. On failure the machine is left unloaded.
  LoadStatus load(const uint8_t* image, size_t image_size, const MachineConfig& config,
                  void* memory, size_t memory_size, Host& host);
  bool loaded() const { return loaded_; }
  const bytecode::ImageView& image() const { return image_; }

  // Starts routine `routine` on `thread` afresh, with `arg_count` inputs.
  RunError start(uint32_t thread, uint32_t routine, const Value* args = nullptr,
                 uint32_t arg_count = 0);
  // start(thread, routine), inline for the usual case: a routine without inputs on a thread that
  // is idle (it finished, or was killed). A cyclic task begins every run so (the S300's PLC62
  // 16 000 times a virtual second).
  RunError restart(uint32_t thread, uint32_t routine);
  // Enters routine `routine` (no inputs) on top of what the thread is doing; when it returns,
  // the thread continues where it was, as it was (running, waiting or halted). An idle or
  // failed thread simply starts the routine; a failed one keeps its last_error() for it.
  RunError interrupt(uint32_t thread, uint32_t routine);
  // Inline below for the usual slice (a running thread at an ordinary instruction): a drive's
  // one-line turns take several each cycle.
  SliceResult run_slice(uint32_t thread, const Budget& budget);

  // A drive's round of one-line turns: a slice of `budget` (no instruction count) for the
  // round's lowest thread, then the next, ... in one entry into the execute loop, which goes on
  // to the next thread only while each slice ends at a line end, without a call to the host
  // (which may have changed which threads run next) and not before a program's bare end, nor
  // before a thread that is not running at an ordinary instruction (waiting, stopped, at a
  // breakpoint). round.at is the last thread run; its result is returned, the
  // earlier ones ended at their line end. NotRunning, with nothing run and round.at the lowest
  // thread, when that one cannot start in a round: run_slice takes those.
  SliceResult run_round(Round& round, const Budget& budget);
  // Where the next instruction ends the program without being part of any line: an EXIT, or a
  // RET from the outermost frame.
  bool at_bare_end(uint32_t thread) const;

  void halt(uint32_t thread);    // a running or waiting thread stops where it is
  void resume(uint32_t thread);  // a halted thread, or one at a breakpoint, runs again
  void kill(uint32_t thread);    // drops the thread's frames; it becomes idle

  ThreadStatus status(uint32_t thread) const;  // inline below: firmware asks it every cycle
  // Threads 0..31 in status `s`, one bit each (a thread from 32 on is in none): a schedule
  // reads which threads may take a turn without looking at each of them.
  uint32_t threads_in(ThreadStatus s) const { return in_status_[static_cast<uint8_t>(s)]; }
  // In a timed wait whose time has not come: a slice would run nothing (inline below).
  bool sleeping(uint32_t thread);
  RunError last_error(uint32_t thread) const;
  int32_t error_detail(uint32_t thread) const;             // the drive's code for CommandRefused
  uint32_t pc(uint32_t thread) const;                      // inline below, as status()
  uint32_t frame_count(uint32_t thread) const;             // inline below
  FrameInfo frame(uint32_t thread, uint32_t depth) const;  // depth 0 is the innermost
  // The outputs of the routine started by start(), readable after it finished.
  uint32_t thread_count() const { return thread_count_; }

  // Globals, checked: false when the index or element is out of range.
  bool read_global(uint32_t global, uint32_t element, Value& out) const;
  bool write_global(uint32_t global, uint32_t element, Value value);
  // Places a global on the host's own words (a controller's general data, which the host reads
  // and writes too and which outlives a program): the program's loads and stores reach them
  // from now on. `data` must stay valid while this image is loaded; LDM and STM still reach the
  // words set aside at load. False when the index is out of range or `length` too short.
  bool bind_global(uint32_t global, Value* data, uint32_t length);
  // A global's words (where it is bound, else its place in the data memory), for binding it into
  // another machine that shares it (a host line's over the program's); empty when out of range.
  std::span<Value> global_words(uint32_t global) {
    if (global >= global_count_) return {};
    return {global_data_[global], global_length_[global]};
  }
  std::span<const Value> global_words(uint32_t global) const {
    if (global >= global_count_) return {};
    return {global_data_[global], global_length_[global]};
  }
  // The data memory: every global's words in table order, global 0's element 0 at address 0,
  // as LDM and STM see it. Checked: false when the address is past the last word.
  uint32_t memory_words() const { return memory_words_; }
  // All of it, read-only, for a reader that samples it (the drive's recorder); empty unloaded.
  std::span<const Value> memory() const { return {memory_, loaded_ ? memory_words_ : 0u}; }
  bool read_memory(uint32_t address, Value& out) const;
  bool write_memory(uint32_t address, Value value);
  // Locals of a frame, for the debugger.
  bool read_local(uint32_t thread, uint32_t depth, uint32_t local, Value& out) const;
  bool write_local(uint32_t thread, uint32_t depth, uint32_t local, Value value);
  // The thread's expression stack, every frame's, bottom first (empty when idle).
  std::span<const Value> operand_stack(uint32_t thread) const;
  // Moves a halted thread to `pc` in its innermost frame's routine, its stack kept, when the
  // verifier's paths from that routine's entry reach `pc` with the stack as deep as the frame's
  // is now (a debugger's "set next statement"; Akribis' AProgPointer). A wait it stood in is
  // left. `scratch`: bytecode::verify_scratch_size(image()) bytes, aligned for uint32_t. False,
  // with nothing changed, otherwise.
  bool move_pc(uint32_t thread, uint32_t pc, void* scratch, size_t scratch_size);

  // False when pc is not an instruction or the table is full.
  bool set_breakpoint(uint32_t pc);
  bool clear_breakpoint(uint32_t pc);

 private:
  struct RoutineInfo {
    uint32_t entry;
    uint32_t inputs;
    uint32_t outputs;
    uint32_t locals;
  };
  enum class FrameKind : uint8_t { Call, Event };
  struct Frame {
    uint32_t return_pc;
    uint32_t routine;
    Value* locals;      // this frame's locals
    Value* stack_base;  // the caller's stack top once the inputs are consumed
    uint32_t saved_wake_us;
    uint8_t nargout;
    FrameKind kind;
    ThreadStatus saved_status;
  };
  struct Handler {
    uint32_t catch_pc;
    uint32_t frame_count;
    Value* sp;
    Value* locals_top;
    bool catches_events;  // TRYALL: the errors of event routines entered above it too
  };
  struct Breakpoint {
    uint32_t pc;
    uint32_t original;
  };
  struct Thread {
    ThreadStatus status;
    RunError last_error;
    int32_t error_detail;
    uint32_t pc;
    uint32_t wake_us;
    Value* sp;
    Value* stack;
    Value* locals;
    Value* locals_top;
    Value* locals_end;
    Frame* frames;
    uint32_t frame_count;
    uint32_t status_bit;  // its bit in threads_in()'s masks (none from thread 32 on)
    Handler* handlers;
    uint32_t handler_count;
    bool step_over;  // resumed at a breakpoint: run the original instruction first
    ThreadStatus status_before_halt;
  };

  // Running at an ordinary instruction: a slice goes straight into the execute loop.
  bool starts_plainly(uint32_t thread) const;
  bool starts_plainly(const Thread& t) const;  // of a loaded machine
  bool at_bare_end(const Thread& t) const;
  static bool is_bare_end(bytecode::Op op, uint32_t frame_count) {
    return op == bytecode::Op::EXIT || (op == bytecode::Op::RET && frame_count == 1);
  }
  Thread* next_in_round(Round& round, bytecode::Op next_op, uint32_t frame_count);
  SliceResult run_other_slice(uint32_t thread, const Budget& budget);  // the rest of run_slice
  SliceResult step_over_breakpoint(Thread& t, const Budget& budget);
  SliceResult execute(Thread& t, const Budget& budget, Round* round = nullptr);
  // Enters routine r: pushes a frame, moves the inputs into its locals. False on an error,
  // which is then set in `error`.
  bool enter(Thread& t, uint32_t routine, uint32_t return_pc, uint8_t nargout, FrameKind kind,
             RunError& error);
  void push_frame(Thread& t, uint32_t routine, Value* base, uint32_t return_pc, uint8_t nargout,
                  FrameKind kind);  // enter()'s frame, its checks made
  // Delivers a run-time error: true when a try block caught it and the thread continues.
  bool raise(Thread& t, RunError error, int32_t detail);
  void reset_thread(Thread& t);  // the only way a thread becomes idle: an idle one is reset
  void set_status(Thread& t, ThreadStatus s);  // the status and threads_in() together
  bool is_instruction_start(uint32_t pc) const;
  void unfuse_around(uint32_t pc);
  const Breakpoint* find_breakpoint(uint32_t pc) const;

  bool loaded_ = false;
  bytecode::ImageView image_;
  Host* host_ = nullptr;
  MachineConfig config_;
  uint32_t* code_ = nullptr;
  uint32_t code_size_ = 0;
  Value* constants_ = nullptr;
  RoutineInfo* routines_ = nullptr;
  uint32_t routine_count_ = 0;
  // Each global's words and its length, apart: the execute loop indexes the words of a global
  // on every access and its length only for an index it checks.
  Value** global_data_ = nullptr;
  uint32_t* global_length_ = nullptr;
  uint32_t global_count_ = 0;
  Value* memory_ = nullptr;  // the globals' words, one block
  uint32_t memory_words_ = 0;
  Thread* threads_ = nullptr;
  uint32_t thread_count_ = 0;
  uint32_t in_status_[static_cast<uint8_t>(ThreadStatus::Error) + 1] = {};
  uint32_t max_depth_ = 0;  // the deepest any frame's expression stack goes (from the verifier)
  Breakpoint* breakpoints_ = nullptr;
  uint32_t breakpoint_count_ = 0;
};

inline RunError Machine::restart(uint32_t thread, uint32_t routine) {
  // An idle thread is reset: no frame, its stack and locals free, so of start()'s checks only
  // the locals' is left (load() refuses no frames, the verifier a depth beyond the stack).
  if (!loaded_ || thread >= thread_count_ || routine >= routine_count_ ||
      threads_[thread].status != ThreadStatus::Idle || routines_[routine].inputs != 0 ||
      routines_[routine].locals > config_.locals)
    return start(thread, routine);
  Thread& t = threads_[thread];
  set_status(t, ThreadStatus::Running);
  push_frame(t, routine, t.stack, 0, 0, FrameKind::Call);
  t.last_error = RunError::None;
  return RunError::None;
}
inline bool Machine::starts_plainly(uint32_t thread) const {
  return loaded_ && thread < thread_count_ && starts_plainly(threads_[thread]);
}
inline bool Machine::starts_plainly(const Thread& t) const {
  return t.status == ThreadStatus::Running && !t.step_over;
}
inline SliceResult Machine::run_slice(uint32_t thread, const Budget& budget) {
  if (starts_plainly(thread)) return execute(threads_[thread], budget);
  return run_other_slice(thread, budget);
}
inline SliceResult Machine::run_round(Round& round, const Budget& budget) {
  if (round.threads == 0) return {SliceEnd::NotRunning, 0};
  round.at = static_cast<uint32_t>(std::countr_zero(round.threads));
  // The round ends before its first thread that is not running (a thread the machine lacks is
  // in no status), once here: a line that does not call the host changes no other thread.
  const uint32_t stopped = round.threads & ~threads_in(ThreadStatus::Running);
  round.threads &= (stopped & (0u - stopped)) - 1;  // none stopped: ~0u, all of them
  if (round.threads == 0 || budget.instructions != 0 || !starts_plainly(threads_[round.at]))
    return {SliceEnd::NotRunning, 0};
  return execute(threads_[round.at], budget, &round);
}
// The frame of `routine` on t: its inputs, which end at `base` on the stack, become its first
// locals and the others start at zero. The checks are the caller's (enter(), start(), restart()).
inline void Machine::push_frame(Thread& t, uint32_t routine, Value* base, uint32_t return_pc,
                                uint8_t nargout, FrameKind kind) {
  const RoutineInfo& r = routines_[routine];
  Frame& f = t.frames[t.frame_count++];
  f.return_pc = return_pc;
  f.routine = routine;
  f.locals = t.locals_top;
  f.stack_base = base;
  f.saved_wake_us = t.wake_us;
  f.nargout = nargout;
  f.kind = kind;
  f.saved_status = t.status;
  Value* locals = t.locals_top;
  for (uint32_t i = 0; i < r.inputs; ++i) locals[i] = base[i];
  for (uint32_t i = r.inputs; i < r.locals; ++i) locals[i] = Value::of_bits(0);
  t.locals_top = locals + r.locals;
  t.sp = base;
  t.pc = r.entry;
}

inline bool Machine::at_bare_end(const Thread& t) const {
  return t.pc < code_size_ && is_bare_end(bytecode::word_op(code_[t.pc]), t.frame_count);
}
inline bool Machine::at_bare_end(uint32_t thread) const {
  return thread < thread_count_ && at_bare_end(threads_[thread]);
}
// After a line ended without calling the host, its thread next at `next_op` in `frame_count`
// frames: the round's next thread, or nullptr when the round ends here (its last thread, a
// program's bare end next, a next one that cannot start). The machine is loaded: it runs.
inline Machine::Thread* Machine::next_in_round(Round& round, bytecode::Op next_op,
                                               uint32_t frame_count) {
  const uint32_t later = round.threads & ~((2u << round.at) - 1);  // 2u << 31 is 0: none
  if (later == 0 || is_bare_end(next_op, frame_count)) return nullptr;
  // run_round left only running threads in the round, and a line that does not call the host
  // changes no other thread's status: the next one is still running.
  const auto thread = static_cast<uint32_t>(std::countr_zero(later));
  Thread& t = threads_[thread];
  if (t.step_over) return nullptr;
  round.at = thread;
  return &t;
}
inline void Machine::set_status(Thread& t, ThreadStatus s) {
  in_status_[static_cast<uint8_t>(t.status)] &= ~t.status_bit;
  in_status_[static_cast<uint8_t>(s)] |= t.status_bit;
  t.status = s;
}
// Inline: a program's end resets its thread (a cyclic task's every run).
inline void Machine::reset_thread(Thread& t) {
  set_status(t, ThreadStatus::Idle);
  t.pc = 0;
  t.wake_us = 0;
  t.sp = t.stack;
  t.locals_top = t.locals;
  t.frame_count = 0;
  t.handler_count = 0;
  t.step_over = false;
  t.status_before_halt = ThreadStatus::Running;
}
inline ThreadStatus Machine::status(uint32_t thread) const {
  return thread < thread_count_ ? threads_[thread].status : ThreadStatus::Idle;
}
inline bool Machine::sleeping(uint32_t thread) {
  return status(thread) == ThreadStatus::Waiting &&
         static_cast<int32_t>(host_->now_us() - threads_[thread].wake_us) < 0;
}
inline uint32_t Machine::pc(uint32_t thread) const {
  return thread < thread_count_ ? threads_[thread].pc : 0;
}
inline uint32_t Machine::frame_count(uint32_t thread) const {
  return thread < thread_count_ ? threads_[thread].frame_count : 0;
}

}  // namespace uprog::vm
