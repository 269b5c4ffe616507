// The Gold firmware's lifecycle: boot, the program store (download, CC), starting the program,
// and the Host the VM talks to. The background is in background.cpp, the command line in
// command_line.cpp and program_control.cpp.
#include "dialects/gold/firmware.h"

#include <fmt/core.h>

#include <charconv>

#include "dialect/program_store.h"
#include "dialects/gold/background_cycle.h"
#include "dialects/gold/commands.h"
#include "dialects/gold/recorder_signals.h"
#include "drive/axis.h"
#include "vm/run_error.h"

namespace uprog::gold {
namespace {

uint16_t command_id(std::string_view name) { return find_command(name)->id; }

// The commands the firmware answers itself. Looked up once at start-up rather than behind a
// function-local static's guard: a program reads a drive command nearly every servo cycle.
const uint16_t kMi = command_id("MI"), kPs = command_id("PS"), kEc = command_id("EC");

const vm::MachineConfig kProgramConfig{};
const dialect::ProgramStore kProgramStore{"program.upi", "program"};
constexpr std::string_view kDialectName = "gold";  // what the Gold compiler writes into its images

}  // namespace

dialect::FramerOptions command_line_framing() {
  dialect::FramerOptions o;
  o.max_line_length = 511;
  o.semicolon_ends_line = true;
  o.comment_marker = "**";
  return o;
}

Firmware::Firmware(dialect::Runtime& runtime, const dialect::FirmwareOptions& options)
    : runtime_(runtime),
      options_(options),
      wire_(options.wire_style, command_line_framing(),
            [this] { return drive_commands_ && drive_commands_->echo(); }),
      schedule_(options.timing),
      slice_budget_(schedule_.budget()),
      background_us_(options.timing.background_us) {}

// The firmware's cycle is a background pass (manual 2.2, background_cycle.h); the servo cycle
// is the axis's.
uint64_t Firmware::cycle_ns() const {
  return background_pass_ns(axis_->period_us(), background_us_);
}

uint64_t Firmware::servo_cycle_ns() const {
  const uint32_t period_us = axis_->period_us();
  return uint64_t{period_us == 0 ? 50u : period_us} * 1000;
}

// `background 500us` fixes the pass, `background auto` returns to the model's (a transcript's
// directive, docs/transcripts.md).
bool Firmware::world_directive(std::string_view name, std::string_view arg, std::string& failure) {
  if (name != "background") return false;
  if (arg == "auto") {
    background_us_ = 0;
    return true;
  }
  if (arg.ends_with("us")) arg.remove_suffix(2);
  uint32_t us = 0;
  const auto [end, ec] = std::from_chars(arg.data(), arg.data() + arg.size(), us);
  if (ec != std::errc() || end != arg.data() + arg.size() || us < 1 || us > kMaxBackgroundUs) {
    failure = fmt::format("background takes 'auto' or 1..{}us", kMaxBackgroundUs);
    return true;
  }
  background_us_ = us;
  return true;
}

// Power-up and RS: the controller has made a fresh axis with the saved parameters; the stored
// program goes into RAM and AUTOEXEC starts.
void Firmware::boot(std::vector<std::string>& messages) {
  axis_ = &runtime_.axis();
  drive_commands_ = std::make_unique<DriveCommands>(*axis_);
  // SR's program bits (12 running, 29 stopped by an error) are the firmware's to tell.
  drive_commands_->set_program_state_source([this] {
    return ProgramState{program_status() == 1, program_error_ != vm::RunError::None};
  });
  recorder_map_.clear();
  ec_ = 0;
  if (!flash_read_) {
    flash_read_ = true;  // once, at power-up: RS keeps what is stored
    stored_ = kProgramStore.read(
        runtime_.flash(), [this](const std::vector<uint8_t>& b) { return verify(b).error; },
        messages, "; the drive starts without a program");
  }
  unload();
  std::string error;
  if (stored_ && load_stored(&error) != 0) messages.push_back(error);
  if (program_ && !options_.safe_boot) {
    if (auto r = autos_.routine_of(kAutoExec)) {
      log("AUTOEXEC started");
      // AUTOEXEC is the program's entry at power-up, not an interruption: it blocks nothing.
      start_program(*r, nullptr, 0);
    }
  }
}

dialect::DownloadResult Firmware::verify(const std::vector<uint8_t>& bytes) {
  dialect::DownloadResult r;
  // The verifier runs inside the load; the scratch program is then dropped.
  if (!dialect::LoadedProgram::load(bytes, kProgramConfig, *this, &r.error, false, kDialectName))
    return r;
  r.ok = true;
  return r;
}

dialect::DownloadResult Firmware::download(const std::vector<uint8_t>& bytes) {
  dialect::DownloadResult r = verify(bytes);
  if (!r.ok) return r;
  r = kProgramStore.store(runtime_.flash(), bytes);
  if (!r.ok) return r;
  stored_ = bytes;
  forget_recorder_variables();
  log("program downloaded (" + std::to_string(bytes.size()) + " bytes)");
  return r;
}

// Manual 2.16: "The command DB##RV[N]=varname is needed after each user program download": a
// new program's variables are not the old one's, so every RV[n] that named one records nothing.
void Firmware::forget_recorder_variables() {
  const uint16_t rv = find_command("RV")->id;
  RecorderCommands& recorder = drive_commands_->recorder();
  for (int32_t n = 1; n <= static_cast<int32_t>(kRecorderSlots); ++n) {
    Value signal;
    if (recorder.read(rv, n, signal) == 0 && signal.i == kRecorderVariableSignal)
      (void)recorder.write(rv, n, Value::of_int(0));
  }
}

void Firmware::unload() {
  if (bound_line_running_)
    retired_program_ = std::move(program_);
  else
    program_.reset();
  known_globals_.clear();
  autos_.clear();
  ever_run_ = false;
  program_error_ = vm::RunError::None;
  program_error_detail_ = 0;
  ++program_generation_;
}

int32_t Firmware::load_stored(std::string* error) {
  if (!stored_) {
    if (error) *error = "no program has been downloaded";
    return kErrorNoStoredProgram;
  }
  unload();
  std::string why;
  program_ =
      dialect::LoadedProgram::load(*stored_, kProgramConfig, *this, &why, true, kDialectName);
  if (!program_) {
    if (error) *error = "stored program refused: " + why;
    unload();
    return kErrorStorage;
  }
  known_globals_ = known_globals(program_->image());
  autos_.bind(program_->machine().image());
  return 0;
}

int32_t Firmware::start_program(uint32_t routine, const Value* args, uint32_t n) {
  autos_.forget_activity();
  const vm::RunError e = machine()->start(kProgramThread, routine, args, n);
  if (e != vm::RunError::None) return kErrorBadArguments;
  ever_run_ = true;
  program_error_ = vm::RunError::None;
  program_error_detail_ = 0;
  return 0;
}

int32_t Firmware::execute_program(std::string_view name, const std::vector<double>& args) {
  if (!program_) return kErrorNoProgram;
  if (program_status() == 1) return kErrorProgramRunning;
  const bytecode::Image& image = program_->image();
  const int r = image.find_routine(std::string(name));
  if (r < 0) return kErrorNoSuchEntry;
  const bytecode::Routine& routine = image.routines[static_cast<size_t>(r)];
  if (args.size() != routine.inputs) return kErrorBadArguments;
  std::vector<Value> values;
  for (size_t i = 0; i < args.size(); ++i) {
    const bool is_float = i < routine.locals.size() && routine.locals[i].type == ValueType::Float;
    if (is_float) {
      values.push_back(Value::of_float(static_cast<float>(args[i])));
    } else {
      if (args[i] != static_cast<double>(static_cast<int64_t>(args[i])) || args[i] > 2147483647.0 ||
          args[i] < -2147483648.0) {
        return kErrorBadArguments;
      }
      values.push_back(Value::of_int(static_cast<int32_t>(args[i])));
    }
  }
  if (machine()->status(kProgramThread) != vm::ThreadStatus::Idle) machine()->kill(kProgramThread);
  const int32_t code =
      start_program(static_cast<uint32_t>(r), values.data(), static_cast<uint32_t>(values.size()));
  if (code == 0) log("program started at " + std::string(name));
  return code;
}

// As `uprog run` starts a program: CC, then XQ## at `entry`, or without one at main, else
// AUTOEXEC, else the first function or label of the file.
std::string Firmware::start(std::string_view entry) {
  std::string error;
  if (load_stored(&error) != 0) return error;
  std::vector<std::string> entries = {std::string(entry)};
  if (entry.empty()) {
    entries = {"main", "AUTOEXEC"};
    for (const bytecode::Routine& r : program_->image().routines) {
      if (r.kind == bytecode::RoutineKind::Function || r.kind == bytecode::RoutineKind::Label) {
        entries.push_back(r.name);
        break;
      }
    }
  }
  int32_t code = -1;
  for (const std::string& e : entries) {
    code = execute_program(e, {});
    if (code == 0) return "";
  }
  return fmt::format("cannot start at '{}' (error {})", entry.empty() ? "main" : entry, code);
}

int32_t Firmware::program_status() const {
  if (!program_) return -2;
  if (!ever_run_) return -1;
  switch (program_->machine().status(kProgramThread)) {
    case vm::ThreadStatus::Running:
    case vm::ThreadStatus::Waiting:
      return 1;
    default:
      return 0;
  }
}

std::string Firmware::program_error_text() const {
  return program_error_ == vm::RunError::None ? std::string() : vm::run_error_text(program_error_);
}

std::string Firmware::state_summary() const {
  drive::Axis& axis = runtime_.axis();
  return fmt::format("PS={} PX={} VX={} MO={} MF={}", program_status(), axis.position(),
                     axis.velocity(), axis.motor_on() ? 1 : 0, axis.motor_fault());
}

std::vector<dialect::ThreadInfo> Firmware::threads() const {
  if (!program_) return {};
  const vm::Machine& m = program_->machine();
  dialect::ThreadInfo t;
  t.thread = kProgramThread;
  t.name = "program";
  t.status = m.status(kProgramThread);
  if (t.status != vm::ThreadStatus::Idle) t.where = program_->where(m.pc(kProgramThread));
  t.error = static_cast<int32_t>(program_error_);
  return {t};
}

// --- Host ---

vm::CommandStatus Firmware::read(uint32_t command, int32_t index, Value& out) {
  if (command == kMi || command == kPs || command == kEc) {
    if (index != 0) return kErrorBadIndex;
    out = Value::of_int(command == kMi   ? static_cast<int32_t>(autos_.mask())
                        : command == kPs ? program_status()
                                         : ec_);
    return vm::kCommandOk;
  }
  if (command > 0xFFFF) return kErrorBadCommand;
  const int32_t r = drive_commands_->read(static_cast<uint16_t>(command), index, out);
  return r == kErrorNotHandledHere ? kErrorNoValue : r;
}

vm::CommandStatus Firmware::write(uint32_t command, int32_t index, Value value) {
  if (command == kMi) {
    if (index != 0) return kErrorBadIndex;
    if (value.i < 0 || value.i > 65535) return kErrorOutOfRange;
    autos_.set_mask(static_cast<uint32_t>(value.i));
    return vm::kCommandOk;
  }
  if (command == kPs || command == kEc) return kErrorReadOnly;
  if (command > 0xFFFF) return kErrorBadCommand;
  const int32_t r = drive_commands_->write(static_cast<uint16_t>(command), index, value);
  return r == kErrorNotHandledHere ? kErrorNotAssignable : r;
}

vm::CommandStatus Firmware::execute(uint32_t command, int32_t index, const Value*, uint32_t) {
  if (command > 0xFFFF) return kErrorBadCommand;
  const int32_t r = drive_commands_->execute(static_cast<uint16_t>(command), index);
  // Program control from inside a program or a compiled line is not offered: the command line
  // handles XQ, HP, XC, KL, CC, LS, SV, LD, RS and DB as text (program_control.cpp).
  return r == kErrorNotHandledHere ? kErrorNoValue : r;
}

}  // namespace uprog::gold
