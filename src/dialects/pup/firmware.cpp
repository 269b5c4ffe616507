// The AG300 firmware's lifecycle: boot, the program store (a download is read strictly, loaded
// and only then stored), threads on rate priorities, their run-time errors, and the VM's Host.
#include "dialects/pup/firmware.h"

#include <fmt/core.h>

#include <filesystem>

#include "bytecode/opcodes.h"
#include "dialect/program_store.h"
#include "dialects/pup/cup_math.h"
#include "drive/axis.h"
#include "vm/run_error.h"

namespace uprog::pup {
namespace {

const dialect::ProgramStore kProgramStore{"program.cup", "program"};

vm::MachineConfig machine_config() {
  vm::MachineConfig c;
  c.threads = kThreads + 1;
  c.stack = 50;
  c.frames = 31;  // the task's own and 30 calls (ProgCallStack "max. depth 30")
  c.locals = 16;
  return c;
}

// The controller's code for a VM error (the spec's error list).
int32_t code_of(vm::RunError e, int32_t detail) {
  switch (e) {
    case vm::RunError::CommandRefused:
      return detail;
    case vm::RunError::DivisionByZero:
      return 30;
    case vm::RunError::Domain:  // an intrinsic's argument (AMath[8], [9], [33], ...)
      return 31;
    case vm::RunError::StackOverflow:
      return 26;
    case vm::RunError::CallDepth:
    case vm::RunError::InterruptDepth:
      return 28;
    case vm::RunError::IndexOutOfRange:
      return 4;
    default:
      return 2;
  }
}

}  // namespace

Firmware::Firmware(dialect::Runtime& runtime, const dialect::FirmwareOptions&)
    : runtime_(runtime),
      wire_(dialect::FramerOptions{}, [this](int32_t code) { on_framing_error(code); }),
      schedule_(scheduling::RatePrioritiesConfig{}) {}

void Firmware::boot(std::vector<std::string>& messages) {
  axis_ = &runtime_.axis();
  gen_data_.fill(Value::of_int(0));
  timers_.fill(0);
  line_stack_.clear();
  // The keywords' values are RAM (a fresh axis takes the drive's defaults); the analog input is
  // the world's and keeps its level.
  motion_mode_ = 0, speed_ = 10000, ain_factor_ = 1, ain_offset_ = 0, curr_cmd_ = 0;
  abs_trgt_ = 0, rel_trgt_ = 0;
  in_func_.fill(0);
  if (!flash_read_) {
    flash_read_ = true;
    // Checked just below, by the install that loads it.
    if (auto bytes = kProgramStore.read(runtime_.flash(), nullptr, messages))
      stored_ = std::string(bytes->begin(), bytes->end());
  }
  if (stored_) {
    const std::string why = install(*stored_, false);
    if (!why.empty()) {
      messages.push_back("stored program " + runtime_.flash().where(kProgramStore.record()) +
                         " refused: " + why);
      stored_.reset();
    }
  }
}

// Reads, checks and loads a CUP file; the threads are idle and the state reset after it.
std::string Firmware::install(const std::string& cup, bool store) {
  CupReadError read_error;
  auto program = read_cup(cup, &read_error);
  if (!program) return fmt::format("error {}: {}", read_error.code, read_error.text);
  std::string why;
  auto loaded = load_cup(*program, &why);
  if (!loaded) return "error 45: " + why;
  apply_debug_map(cup, loaded->image);
  auto image = dialect::LoadedProgram::load(bytecode::encode(loaded->image), machine_config(),
                                            *this, &why, true, "pup");
  if (!image) return "error 45: " + why;
  if (!bind_gen_data(image->machine(), *loaded, gen_data_))
    return "error 45: AGenData cannot be placed";
  if (store) {
    const dialect::DownloadResult stored =
        kProgramStore.store(runtime_.flash(), std::vector<uint8_t>(cup.begin(), cup.end()));
    if (!stored.ok) return "error 46: " + stored.error;
  }
  program_ = std::move(image);
  cup_ = std::move(*loaded);
  cup_program_ = std::move(*program);
  schedule_.reset();
  thread_error_.fill(0);
  single_.fill(Single{});
  stepping_ = 0;
  for (auto& b : breaks_) b.clear();
  latched_ = 0;
  event_frames_.clear();
  event_mask_ = 0x00FFFFFF;
  line_stack_.clear();  // the manual: "the stack is cleared upon downloading of a new user program"
  previous_inputs_ = axis_->input_level_bits();
  if (store) stored_ = cup;
  return "";
}

dialect::DownloadResult Firmware::download(const std::vector<uint8_t>& bytes) {
  dialect::DownloadResult r;
  r.error = install(std::string(bytes.begin(), bytes.end()), true);
  r.ok = r.error.empty();
  r.storage_failed = r.error.starts_with("error 46");
  if (r.ok) runtime_.log(fmt::format("program downloaded ({} bytes)", bytes.size()));
  return r;
}

int32_t Firmware::run_task(uint32_t thread, int32_t task) {
  if (!program_) return 15;
  if (task < 0 || task > 64 || cup_.task_routine[static_cast<size_t>(task)] < 0) return 33;
  const vm::ThreadStatus s = program_->machine().status(thread);
  if (s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting) return 17;
  program_->machine().kill(thread);
  program_->machine().start(thread,
                            static_cast<uint32_t>(cup_.task_routine[static_cast<size_t>(task)]));
  schedule_.started(thread);
  thread_error_[thread] = 0;
  return 0;
}

std::string Firmware::start(std::string_view entry) {
  if (!program_) return "no program has been downloaded";
  int32_t task = -1;
  if (!entry.empty()) {
    const auto n = parse_number(entry);
    if (!n) return fmt::format("'{}' is no task number", entry);
    task = *n;
  } else {
    for (int32_t t = 0; t <= 64 && task < 0; ++t) {
      if (cup_.task_routine[static_cast<size_t>(t)] >= 0) task = t;
    }
  }
  const int32_t code = run_task(1, task);
  return code == 0 ? "" : fmt::format("cannot run task {} (error {})", task, code);
}

void Firmware::cycle(const std::vector<uint32_t>& drive_events) {
  timer_us_ += 50;
  if (timer_us_ >= 1000) {
    timer_us_ -= 1000;
    for (size_t n = 0; n < timers_.size(); ++n) {
      if (timers_[n] <= 0) continue;
      if (--timers_[n] == 0) latch(18 + static_cast<int32_t>(n));
    }
  }
  if (!program_) return;
  latch_events(drive_events.empty() ? 0 : drive_events[0]);
  // Most cycles have no event to take or to return from, and no thread event to react to.
  if (latched_ != 0) take_event();
  const scheduling::Report report = schedule_.cycle(program_->machine());
  for (uint32_t t = 1; report.threads_with_events() != 0 && t <= kThreads; ++t) {
    if (report.has(t, scheduling::ThreadEvent::Error)) on_thread_error(t);
  }
  if (!event_frames_.empty()) check_event_return();
  if ((report.threads_with_events() | stepping_) != 0) after_cycle(report);
}

void Firmware::on_thread_error(uint32_t thread) {
  const vm::Machine& m = program_->machine();
  const int32_t code = code_of(m.last_error(thread), m.error_detail(thread));
  thread_error_[thread] = code;
  if (thread == 1)
    reset_events();  // the held threads resume; no event is raised
  else
    latch(22);
  log_error(code, static_cast<int32_t>(thread), static_cast<int32_t>(cup_.line_of(m.pc(thread))));
  // The source's place: the PUP line when the build's debug map came with the program, else the
  // CUP line.
  runtime_.log(fmt::format("thread {}: run-time error {} at {}", thread, code,
                           program_->where(m.pc(thread))));
}

void Firmware::log_error(int32_t code, int32_t source, int32_t line) {
  err_log_.insert(err_log_.begin(), {code, source, line});
  if (err_log_.size() > 16) err_log_.pop_back();
}

bool Firmware::running() const {
  for (uint32_t t = 1; t <= kThreads; ++t) {
    const int32_t s = program_status(t);
    if (s == 1 || s == 2) return true;
  }
  return false;
}

// AProgStatus: 0 idle, 1 running, 2 waiting, 3 halted, 4 breakpoint, 5 error, 6 held.
int32_t Firmware::program_status(uint32_t thread) const {
  if (!program_) return 0;
  switch (program_->machine().status(thread)) {
    case vm::ThreadStatus::Idle:
      return 0;
    case vm::ThreadStatus::Running:
      if (schedule_.held(thread)) return 6;
      return cup_.waits[cup_.line_of(program_->machine().pc(thread))] ? 2 : 1;
    case vm::ThreadStatus::Waiting:
      return schedule_.held(thread) ? 6 : 2;
    case vm::ThreadStatus::Halted:
      return 3;
    case vm::ThreadStatus::AtBreakpoint:
      return 4;
    case vm::ThreadStatus::Error:
      return 5;
  }
  return 0;
}

int32_t Firmware::program_error() const {
  for (uint32_t t = 1; t <= kThreads; ++t) {
    if (thread_error_[t] != 0) return thread_error_[t];
  }
  return 0;
}

std::string Firmware::program_error_text() const {
  const int32_t e = program_error();
  return e == 0 ? "" : fmt::format("controller error {}", e);
}

std::string Firmware::state_summary() const {
  return fmt::format("AProgStatus[1]={} APos={} AVel={} AMotorOn={} AMotorFault={}",
                     program_status(1), axis_->position(), axis_->velocity(),
                     axis_->motor_on() ? 1 : 0, axis_->motor_fault());
}

std::vector<dialect::ThreadInfo> Firmware::threads() const {
  std::vector<dialect::ThreadInfo> out;
  if (!program_) return out;
  const vm::Machine& m = program_->machine();
  for (uint32_t t = 1; t <= kThreads; ++t) {
    dialect::ThreadInfo info;
    info.thread = t;
    info.name = fmt::format("thread {}", t);
    info.status = m.status(t);
    if (info.status != vm::ThreadStatus::Idle) info.where = place_of(cup_.line_of(m.pc(t)));
    info.error = thread_error_[t];
    out.push_back(std::move(info));
  }
  return out;
}

// Where a CUP line comes from: its PUP source line when the debug map is the program's, as the
// debugger speaks, else the CUP file's line.
std::string Firmware::place_of(uint32_t cup_line) const {
  if (debug_map_ && stored_ && *stored_ == debug_map_cup_ && cup_line >= 1 &&
      cup_line <= debug_map_->places.size()) {
    const Location& at = debug_map_->places[cup_line - 1];
    return fmt::format("{}:{}", std::filesystem::path(at.file).filename().string(), at.line);
  }
  return fmt::format("{}:{}", cup_.image.source_name, cup_line);
}

// The CUP line a thread executes next: a pc on the EOL that closes a line after its code (a
// call's, a wait's) is already past that line, unless the thread waits in it. An EOL that is a
// line's only code (a function's marker) is that line still to run.
uint32_t Firmware::next_line(uint32_t thread) const {
  const vm::Machine& m = program_->machine();
  uint32_t pc = m.pc(thread);
  const auto& code = m.image().code;
  const uint32_t line = cup_.line_of(pc);
  const bool closes_line = pc < code.size() && bytecode::word_op(code[pc]) == bytecode::Op::EOL &&
                           cup_.line_pc[line] != pc && cup_.line_of(pc + 1) != line;
  // A thread halted inside an AWaitTime stands on the EOL after its WAIT (resume() takes it back
  // into the wait; once woken it runs the EOL in the same turn): it is at the wait's line.
  const bool halted_in_wait =
      m.status(thread) == vm::ThreadStatus::Halted && cup_.timed_waits[line];
  if (m.status(thread) != vm::ThreadStatus::Waiting && !halted_in_wait && closes_line) ++pc;
  return cup_.line_of(pc);
}

uint32_t Firmware::running_thread() const {
  const uint32_t t = scheduling::running_now(schedule_.running(), debugger_runs_);
  return t == scheduling::kNoThread ? 0 : t;
}

// --- Host: the program's keywords, indexed accesses and statuses ---

vm::CommandStatus Firmware::read(uint32_t command, int32_t index, Value& out) {
  int32_t v = 0, code = 0;
  if (command >= kStatusBase && command < kStatusBase + 16) {
    code = status_of(static_cast<int32_t>(command - kStatusBase), index);
    v = code >= 0 ? code : 0;
    code = code < 0 ? -code : 0;
  } else if (command >= kIndexedBase && command < kFailBase) {
    const IndexedAccess& a = cup_.indexed.at(command - kIndexedBase);
    if (index < 1 || index > a.size) return 4;
    code = read_key(a.key, a.base + index - 1, v);
  } else if (command < static_cast<uint32_t>(KeywordId::kCount)) {
    code = read_key(static_cast<KeywordId>(command), index, v);
  } else {
    return 1;
  }
  out = Value::of_int(v);
  return code;
}

vm::CommandStatus Firmware::write(uint32_t command, int32_t index, Value value) {
  if (command >= kIndexedBase && command < kFailBase) {
    const IndexedAccess& a = cup_.indexed.at(command - kIndexedBase);
    if (index < 1 || index > a.size) return 4;
    return write_key(a.key, a.base + index - 1, value.i);
  }
  if (command >= static_cast<uint32_t>(KeywordId::kCount)) return 1;
  return write_key(static_cast<KeywordId>(command), index, value.i);
}

vm::CommandStatus Firmware::execute(uint32_t command, int32_t index, const Value* args,
                                    uint32_t count) {
  const uint32_t thread = running_thread();
  if (command == kReturnCheck) return program_->machine().frame_count(thread) <= 1 ? 29 : 0;
  if (command >= kFailBase && command < kReturnCheck)
    return static_cast<int32_t>(command - kFailBase);
  if (command >= static_cast<uint32_t>(KeywordId::kCount)) return 1;
  return run_key(static_cast<KeywordId>(command), index, count > 0, count > 0 ? args[0].i : 0,
                 thread);
}

}  // namespace uprog::pup
