// The PDL firmware's lifecycle, schedule and the Host the VM talks to (firmware.h).
#include "dialects/pdl/firmware.h"

#include <fmt/core.h>

#include "dialect/program_store.h"
#include "dialects/pdl/system_names.h"
#include "drive/axis.h"
#include "drive/events.h"
#include "drive/inputs.h"
#include "support/format_message.h"
#include "vm/run_error.h"

namespace uprog::pdl {
namespace {

const dialect::ProgramStore kProgramStore{"program.pdi", "program"};
constexpr std::string_view kDialectName = "pdl";

// A procedure is a VM routine whose frame takes 2 words of the task's stack at least, so a task
// has no more VM frames than its entry's and 128 procedures': the stack's own check (CallDepth,
// pdl-drive.md's accounting) always comes before the VM's limits.
vm::MachineConfig machine_config() {
  vm::MachineConfig c;
  c.threads = kTasks + 1;  // task 0 is the system's: it never runs user code
  c.frames = 1 + static_cast<uint32_t>(kStackWords) / kMinFrameWords;
  c.locals = c.frames * kEntryLocals;
  return c;
}

dialect::FramerOptions pdl_framing() {
  dialect::FramerOptions o;
  o.max_line_length = 511;
  o.semicolon_ends_line = true;
  return o;
}

// The text of an event: `;`, CR and LF would split the line.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == ';' || c == '\r' || c == '\n') c = ' ';
  return text;
}

}  // namespace

Firmware::Firmware(dialect::Runtime& runtime, const dialect::FirmwareOptions&)
    : runtime_(runtime),
      wire_(pdl_framing(), "%L "),
      schedule_(scheduling::PhaseRoundRobinConfig{1, kTasks, 1'000'000}) {}

// Power-up and reset: the controller made fresh axes; tasks idle, memory and states 0, fclk 0,
// then every #task task starts at its place.
void Firmware::boot(std::vector<std::string>& messages) {
  phase_us_ = runtime_.axis(0).period_us() == 0 ? 50 : runtime_.axis(0).period_us();
  fclk_ = 0;
  homed_ = false;
  overrides_.clear();
  schedule_.reset();
  for (uint32_t t = 0; t <= kTasks; ++t) {
    task_error_[t] = 0;
    task_routine_[t] = 0;
    kill_pending_[t] = false;
  }
  const int32_t defaults[7] = {0, 9, 11, 17, 7, 7, 7};
  for (int n = 1; n <= 6; ++n) {
    in_func_[n] = defaults[n];
    for (size_t a = 0; a < runtime_.axis_count(); ++a)
      runtime_.axis(a).set_input_logic(n, defaults[n]);
  }
  if (!flash_read_) {
    flash_read_ = true;
    stored_ = kProgramStore.read(
        runtime_.flash(), [this](const std::vector<uint8_t>& b) { return verify(b); }, messages);
  }
  program_.reset();
  std::string error;
  if (stored_ && !load_stored(&error)) messages.push_back(error);
  if (program_) start_reset_tasks();
}

// "" when `bytes` load into a verified image; else the loader's or the verifier's finding.
std::string Firmware::verify(const std::vector<uint8_t>& bytes) {
  std::string why;
  if (dialect::LoadedProgram::load(bytes, machine_config(), *this, &why, false, kDialectName))
    return "";
  return why.empty() ? "the image is refused" : why;
}

bool Firmware::load_stored(std::string* error) {
  program_.reset();
  variables_.clear();
  last_error_ = 0;
  if (!stored_) {
    if (error) *error = "no program has been downloaded";
    return false;
  }
  std::string why;
  program_ =
      dialect::LoadedProgram::load(*stored_, machine_config(), *this, &why, true, kDialectName);
  if (!program_) {
    if (error) *error = "stored program refused: " + why;
    return false;
  }
  const bytecode::Image& image = program_->image();
  debug_info_ = DebugInfo::read(image.info);
  for (const std::string& info : image.info) {
    // "var NAME KIND RO R W", one per user variable in declaration order (compiler.cpp).
    if (!info.starts_with("var ")) continue;
    HostVariable v;
    char kind[8] = {};
    char name[64] = {};
    int ro = 0;
    if (std::sscanf(info.c_str(), "var %63s %7s %d %d %d", name, kind, &ro, &v.level_read,
                    &v.level_write) != 5)
      continue;
    v.name = name;
    v.kind = kind[1] == 'p' ? 'p' : kind[0] == 's' ? 's' : kind[0] == 'f' ? 'f' : 'l';
    v.read_only = ro != 0;
    const int g = image.find_global(v.name);
    if (g < 0) continue;
    v.global = static_cast<uint32_t>(g);
    v.length = image.globals[static_cast<size_t>(g)].length;
    variables_.push_back(v);
  }
  int32_t address = 0;
  for (HostVariable& v : variables_) {
    v.address = address;
    address += static_cast<int32_t>(v.length);
  }
  return true;
}

void Firmware::start_reset_tasks() {
  for (const bytecode::Task& t : program_->image().tasks) {
    if (t.starts_at_reset && t.number >= 1 && t.number <= kTasks) start_task(t.number, t.routine);
  }
}

int32_t Firmware::start_task(uint32_t task, uint32_t routine) {
  const int32_t base = stack_base(task);
  const auto args = stack_registers(task, Value::of_int(base), base);
  if (machine()->start(task, routine, args.data(), kEntryInputs) != vm::RunError::None)
    return kBadValue;
  task_error_[task] = 0;
  task_routine_[task] = routine;
  return 0;
}

dialect::DownloadResult Firmware::download(const std::vector<uint8_t>& bytes) {
  const dialect::DownloadResult r = kProgramStore.store(
      runtime_.flash(), bytes, [this](const std::vector<uint8_t>& b) { return verify(b); });
  if (!r.ok) return r;
  stored_ = bytes;
  runtime_.log("program downloaded (" + std::to_string(bytes.size()) + " bytes)");
  return r;
}

// As `uprog run` starts a program: at `entry` in task 1, else the #task tasks, else task 1 at
// the start of the code.
std::string Firmware::start(std::string_view entry) {
  std::string error;
  if (!load_stored(&error)) return error;
  fclk_ = 0;
  schedule_.reset();
  const bytecode::Image& image = program_->image();
  if (!entry.empty()) {
    const int r = image.find_routine(std::string(entry));
    // A procedure's routine is no entry: it wants a caller's frame.
    if (r < 0 ||
        (r > 0 && image.routines[static_cast<size_t>(r)].kind == bytecode::RoutineKind::Function))
      return fmt::format("no label '{}' in the program", entry);
    return start_task(1, static_cast<uint32_t>(r)) == 0 ? "" : "cannot start task 1";
  }
  if (!image.tasks.empty()) {
    start_reset_tasks();
    return "";
  }
  return start_task(1, 0) == 0 ? "" : "cannot start task 1";
}

bool Firmware::running() const {
  const vm::Machine* m = machine();
  if (!m) return false;
  for (uint32_t t = 1; t <= kTasks; ++t) {
    const vm::ThreadStatus s = m->status(t);
    if (s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting) return true;
  }
  return false;
}

std::string Firmware::program_error_text() const {
  return last_error_ == 0 ? std::string()
                          : vm::run_error_text(static_cast<vm::RunError>(last_error_));
}

std::string Firmware::state_summary() const {
  drive::Axis& a = runtime_.axis(0);
  return fmt::format("fclk={} task_st={},{},{} pos={} vel={} enable={} err={}", fclk_,
                     task_state(1), task_state(2), task_state(3), a.position(), a.velocity(),
                     a.motor_on() ? 1 : 0, a.motor_fault());
}

std::vector<dialect::ThreadInfo> Firmware::threads() const {
  std::vector<dialect::ThreadInfo> out;
  if (!program_) return out;
  for (uint32_t t = 1; t <= kTasks; ++t) {
    dialect::ThreadInfo i;
    i.thread = t;
    i.name = "task " + std::to_string(t);
    i.status = program_->machine().status(t);
    if (i.status != vm::ThreadStatus::Idle) i.where = program_->where(program_->machine().pc(t));
    i.error = task_error_[t];
    out.push_back(i);
  }
  return out;
}

int32_t Firmware::task_state(uint32_t task) const {
  if (task_error_[task] != 0) return -task_error_[task];
  const vm::Machine* m = machine();
  if (!m) return 0;
  if (schedule_.lock_holder() == task) return 3;
  switch (m->status(task)) {
    case vm::ThreadStatus::Running:
      return 1;
    case vm::ThreadStatus::Waiting:
      return 2;
    // Held by the debugger or hold/t (docs/dialects/pdl.md, "Debug lines").
    case vm::ThreadStatus::Halted:
    case vm::ThreadStatus::AtBreakpoint:
      return 4;
    default:
      return 0;
  }
}

void Firmware::report_error(uint32_t task) {
  const vm::RunError e = machine()->last_error(task);
  task_error_[task] = static_cast<int32_t>(e);
  last_error_ = static_cast<int32_t>(e);
  std::string text = vm::run_error_text(e);
  if (e == vm::RunError::CommandRefused)
    text += fmt::format(" (code {})", machine()->error_detail(task));
  text += " at " + program_->place(machine()->pc(task));
  runtime_.log(fmt::format("task {}: run-time error {} ({})", task, static_cast<int32_t>(e), text));
  runtime_.output(fmt::format("%E {} {} {}\r\n", task, static_cast<int32_t>(e), one_line(text)));
}

// One phase: states refresh, then one command of one task (the axes stepped already).
void Firmware::cycle(const std::vector<uint32_t>& drive_events) {
  ++fclk_;
  if (!overrides_.empty()) overrides_.clear();
  // X_homed latches when the home input becomes active (the axis reports the edge).
  if (!drive_events.empty() && (drive_events[0] & drive::kEventHome) != 0) homed_ = true;
  vm::Machine* m = machine();
  if (!m) return;
  const scheduling::PhaseResult r = schedule_.phase(*m);
  for (uint32_t t = 1; t <= kTasks; ++t) {
    if (r.report.has(t, scheduling::ThreadEvent::Error)) report_error(t);
    if (kill_pending_[t]) {
      kill_pending_[t] = false;
      m->kill(t);
      schedule_.unlock(t);
    }
  }
}

drive::Axis* Firmware::axis(int32_t index) const {
  if (index < 0 || static_cast<size_t>(index) >= runtime_.axis_count()) return nullptr;
  return &runtime_.axis(static_cast<size_t>(index));
}

bool Firmware::state_value(int32_t number) const {
  for (const Override& o : overrides_)
    if (o.number == number) return o.value;
  if (number >= 0 && number < 6) return runtime_.axis(0).input_active(number + 1);
  if (number >= 8 && number < 12) return runtime_.axis(0).output(number - 7);
  if (number < 32) return false;
  drive::Axis* a = axis((number - 32) / 16);
  if (!a) return false;
  const uint32_t ip = a->input_port();
  switch ((number - 32) % 16) {
    case 0:
      return a->profiler_moving();
    case 1:
      return a->motor_on();
    case 2:
      return a->servo_ready();
    case 3:
      return (ip & drive::kIpMainHome) != 0;
    case 4:
      return number == 36 && homed_;
    case 5:
      return (ip & drive::kIpReverseLimit) != 0;
    case 6:
      return (ip & drive::kIpForwardLimit) != 0;
    case 7:
      return a->motor_fault() != 0;
    default:
      return false;
  }
}

// 0 when done, else the host's error code (a program's refused enable is no error: it stays 0).
int32_t Firmware::write_state(int32_t number, bool on, bool from_host) {
  if (number < 0 || number >= kStateCount) return kBadIndex;
  if (number >= 8 && number < 12) {
    runtime_.axis(0).set_output(number - 7, on);
    return 0;
  }
  if (number >= 32 && (number - 32) % 16 == 1) {
    drive::Axis* a = axis((number - 32) / 16);
    if (!a) return kBadIndex;
    const bool ok = a->set_motor_on(on) == drive::Status::kOk && a->motor_on() == on;
    return ok || !from_host ? 0 : kEnableRefused;
  }
  if (number == 36) {
    homed_ = on;
    return 0;
  }
  overrides_.push_back({number, on});
  return 0;
}

vm::CommandStatus Firmware::read_variable(uint32_t id, int32_t index, int32_t& v) const {
  const SystemVariable* s = system_variable_by_id(id);
  if (!s) return kNoSuchVariable;
  if (s->slave) {
    drive::Axis* a = axis(index);
    if (!a) return kBadIndex;
    const drive::Parameters& p = a->parameters();
    switch (id) {
      case 1:
        v = p.speed_counts_per_s;
        return 0;
      case 2:
        v = p.accel_counts_per_s2;
        return 0;
      case 3:
        v = p.decel_counts_per_s2;
        return 0;
      case 4:
        v = p.stop_decel_counts_per_s2;
        return 0;
      case 5:
        v = p.smoothing_ms;
        return 0;
      case 6:
        v = a->absolute_target();
        return 0;
      case 7:
        v = p.jog_velocity_counts_per_s;
        return 0;
      case 9:
        v = a->position();
        return 0;
      case 10:
        v = a->reference_position();
        return 0;
      case 11:
        v = a->velocity();
        return 0;
      case 12:
        v = a->position_error();
        return 0;
      case 13:
        v = static_cast<int32_t>(a->motor_fault());
        return 0;
      default:
        return kReadOnly;
    }
  }
  if (index < 0 || static_cast<uint32_t>(index) >= s->length) return kBadIndex;
  drive::Axis& a = runtime_.axis(0);
  switch (id) {
    case 14:
      v = static_cast<int32_t>(fclk_);
      return 0;
    case 15: {
      uint32_t bits = 0;
      for (int32_t k = 0; k < 32; ++k)
        if (state_value(index * 32 + k)) bits |= 1u << k;
      v = static_cast<int32_t>(bits);
      return 0;
    }
    case 16: {
      uint32_t bits = 0;
      for (int n = 1; n <= 6; ++n)
        if (a.input_active(n)) bits |= 1u << (n - 1);
      v = static_cast<int32_t>(bits);
      return 0;
    }
    case 17:
      v = static_cast<int32_t>(a.output_port());
      return 0;
    case 18:
      if (index < 1) return kBadIndex;
      v = in_func_[index];
      return 0;
    case 19:
      if (index < 1) return kBadIndex;
      v = task_state(static_cast<uint32_t>(index));
      return 0;
    default:
      return kNoSuchVariable;
  }
}

vm::CommandStatus Firmware::write_variable(uint32_t id, int32_t index, int32_t v, bool from_host) {
  const SystemVariable* s = system_variable_by_id(id);
  if (!s) return kNoSuchVariable;
  if (!s->writable()) return kReadOnly;
  if (s->slave) {
    drive::Axis* a = axis(index);
    if (!a) return kBadIndex;
    drive::Parameters& p = a->parameters();
    switch (id) {
      case 1:
      case 2:
      case 3:
      case 4:
        if (v <= 0) return kBadValue;
        (id == 1   ? p.speed_counts_per_s
         : id == 2 ? p.accel_counts_per_s2
         : id == 3 ? p.decel_counts_per_s2
                   : p.stop_decel_counts_per_s2) = v;
        return 0;
      case 5:
        if (v < 0) return kBadValue;
        p.smoothing_ms = v;
        return 0;
      case 6:
        if (!a->servo_ready()) return kServoNotReady;
        a->set_absolute_target(v);
        return a->begin() == drive::Status::kOk ? 0 : kServoNotReady;
      case 7:
        if (v != 0) {
          if (!a->servo_ready()) return kServoNotReady;
          a->set_jog_velocity(v);
          return a->begin() == drive::Status::kOk ? 0 : kServoNotReady;
        }
        [[fallthrough]];
      case 8: {
        if (id == 8 && v != 1 && v != 2) return kBadValue;
        // stop_m=2 (and jvl=0's stop with dcc for 1): the drive's stop with that deceleration.
        const int32_t keep = p.stop_decel_counts_per_s2;
        if (id == 7 || v == 1) p.stop_decel_counts_per_s2 = p.decel_counts_per_s2;
        a->stop();
        p.stop_decel_counts_per_s2 = keep;
        return 0;
      }
      case 9:
        a->set_position(v);
        return 0;
      default:
        return kReadOnly;
    }
  }
  if (index < 0 || static_cast<uint32_t>(index) >= s->length) return kBadIndex;
  switch (id) {
    case 14:
      fclk_ = static_cast<uint32_t>(v);
      return 0;
    case 17:
      runtime_.axis(0).set_output_port(static_cast<uint32_t>(v));
      return 0;
    case 18:
      if (index < 1 || !drive::valid_input_logic(v)) return index < 1 ? kBadIndex : kBadValue;
      in_func_[index] = v;
      for (size_t a = 0; a < runtime_.axis_count(); ++a) runtime_.axis(a).set_input_logic(index, v);
      return 0;
    default:
      (void)from_host;
      return kReadOnly;
  }
}

// --- vm::Host

vm::CommandStatus Firmware::read(uint32_t command, int32_t index, Value& out) {
  if (command == kStateCommand) {
    if (index < 0 || index >= kStateCount) return kBadIndex;
    out = Value::of_int(state_value(index) ? 1 : 0);
    return vm::kCommandOk;
  }
  int32_t v = 0;
  const vm::CommandStatus r = read_variable(command, index, v);
  out = Value::of_int(v);
  return r;
}

vm::CommandStatus Firmware::write(uint32_t command, int32_t index, Value value) {
  if (command == kStateCommand) return write_state(index, value.i != 0, false);
  return write_variable(command, index, value.i, false);
}

vm::CommandStatus Firmware::execute(uint32_t command, int32_t index, const Value* args,
                                    uint32_t count) {
  const uint32_t self = scheduling::running_now(schedule_.running(), debugger_runs_);
  switch (command) {
    case kLockCommand:
      schedule_.lock(self);
      return vm::kCommandOk;
    case kUnlockCommand:
      schedule_.unlock(self);
      return vm::kCommandOk;
    case kRunCommand: {
      if (index < 1 || index > static_cast<int32_t>(kTasks) || count != 1) return kBadTask;
      const uint32_t t = static_cast<uint32_t>(index);
      const vm::ThreadStatus s = machine()->status(t);
      if (s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting) return kTaskBusy;
      if (args[0].i < 0 || static_cast<uint32_t>(args[0].i) >= program_->image().routines.size())
        return kNoSuchLabel;
      return start_task(t, static_cast<uint32_t>(args[0].i));
    }
    case kKillCommand:
      if (index < 1 || index > static_cast<int32_t>(kTasks)) return kBadTask;
      kill_pending_[index] = true;
      // Killing itself ends the task's turn now; another task ends after this phase.
      return static_cast<uint32_t>(index) == self ? vm::kCommandEndSlice : vm::kCommandOk;
    default:
      return kUnknownCommand;
  }
}

// printl: `%P t MODE1 MODE2 text` to every host; the modes are the first two words.
vm::CommandStatus Firmware::message(uint32_t thread, uint32_t text, const Value* args,
                                    uint32_t count) {
  if (count < 2 || !program_) return kBadValue;
  const std::string body =
      format_message(program_->machine().image().text(text), args + 2, count - 2);
  runtime_.output(fmt::format("%P {} {:08X} {:08X} {}\r\n", thread,
                              static_cast<uint32_t>(args[0].i), static_cast<uint32_t>(args[1].i),
                              one_line(body)));
  return vm::kCommandOk;
}

}  // namespace uprog::pdl
