// Controller lifecycle: boot, the program store (download, CC), starting the program, and the
// Host the VM talks to. Time is in scheduler.cpp, the command line in command_line.cpp.
#include "controller/controller_impl.h"

#include <filesystem>

#include "bytecode/image_view.h"
#include "dialects/gold/commands.h"
#include "drive/parameter_store.h"
#include "support/files.h"
#include "vm/run_error.h"

namespace uprog::controller {
namespace {

uint16_t command_id(std::string_view name) { return gold::find_command(name)->id; }

// The commands the controller answers itself. Looked up once at start-up rather than behind a
// function-local static's guard: a program reads a drive command nearly every servo cycle.
const uint16_t kMi = command_id("MI"), kPs = command_id("PS"), kEc = command_id("EC");

const vm::MachineConfig kProgramConfig{};

std::string program_path(const ControllerOptions& o) { return o.state_dir + "/program.upi"; }

}  // namespace

Controller::Impl::Impl(ControllerOptions opts) : options(std::move(opts)) {
  if (!options.state_dir.empty()) {
    std::error_code ec_ignored;
    std::filesystem::create_directories(options.state_dir, ec_ignored);
    std::string error;
    if (auto bytes = read_binary_file(program_path(options), &error)) {
      const DownloadResult r = verify(*bytes, nullptr);
      if (r.ok) {
        stored_image = std::move(*bytes);
        has_stored = true;
      } else {
        boot_messages.push_back("stored program " + program_path(options) + " refused: " + r.error +
                                "; the drive starts without a program");
      }
    }
  }
  boot();
}

void Controller::Impl::log(std::string text) { log_entries.push_back({now_us_, std::move(text)}); }

// Power-up and RS: a fresh axis with the saved parameters, the stored program in RAM, AUTOEXEC.
void Controller::Impl::boot() {
  axis = std::make_unique<drive::Axis>();
  drive_commands = std::make_unique<gold::DriveCommands>(*axis);
  recorder_map.clear();
  ec = 0;
  std::string error;
  if (!options.state_dir.empty()) {
    const std::string path = options.state_dir + "/parameters.txt";
    if (std::filesystem::exists(path)) {
      if (auto params = drive::load_parameters(path, &error)) {
        axis->load_parameters(*params);
      } else {
        boot_messages.push_back("saved parameters refused: " + error + "; using defaults");
      }
    }
  } else if (saved_parameters) {
    if (auto params = drive::parse_parameters(*saved_parameters)) axis->load_parameters(*params);
  }
  unload();
  if (has_stored && load_stored(&error) != 0) boot_messages.push_back(error);
  if (machine && !options.safe_boot) {
    if (auto r = autos.routine_of(kAutoExec)) {
      log("AUTOEXEC started");
      // AUTOEXEC is the program's entry at power-up, not an interruption: it blocks nothing.
      start_program(*r, nullptr, 0);
    }
  }
}

DownloadResult Controller::Impl::verify(const std::vector<uint8_t>& bytes, bytecode::Image* decoded) {
  DownloadResult r;
  bytecode::ImageView view;
  const bytecode::LoadError le = bytecode::load_image(bytes.data(), bytes.size(), view);
  if (le != bytecode::LoadError::Ok) {
    r.error = std::string("not a valid image: ") + bytecode::load_error_text(le);
    return r;
  }
  // The verifier runs inside Machine::load; the scratch machine is then dropped.
  std::vector<uint64_t> memory((vm::Machine::memory_needed(view, kProgramConfig) + 7) / 8);
  vm::Machine scratch;
  const vm::LoadStatus s =
      scratch.load(bytes.data(), bytes.size(), kProgramConfig, memory.data(), memory.size() * 8, *this);
  if (!s.ok()) {
    if (s.load != bytecode::LoadError::Ok) {
      r.error = std::string("not a valid image: ") + bytecode::load_error_text(s.load);
    } else if (s.verify != bytecode::VerifyError::Ok) {
      r.error = std::string("the verifier refused it: ") + bytecode::verify_error_text(s.verify) +
                " at code word " + std::to_string(s.pc);
    } else {
      r.error = "it needs more memory than the drive has";
    }
    return r;
  }
  std::string error;
  if (decoded != nullptr && !bytecode::decode(bytes.data(), bytes.size(), *decoded, error)) {
    r.error = "not a valid image: " + error;
    return r;
  }
  r.ok = true;
  return r;
}

DownloadResult Controller::Impl::download(const std::vector<uint8_t>& bytes) {
  DownloadResult r = verify(bytes, nullptr);
  if (!r.ok) return r;
  if (!options.state_dir.empty()) {
    std::string error;
    if (!write_file_atomically(program_path(options), bytes.data(), bytes.size(), &error)) {
      r.ok = false;
      r.storage_failed = true;
      r.error = "could not store the program: " + error;
      return r;
    }
  }
  stored_image = bytes;
  has_stored = true;
  log("program downloaded (" + std::to_string(bytes.size()) + " bytes)");
  return r;
}

void Controller::Impl::unload() {
  machine.reset();
  ram_image.clear();
  ram_decoded = bytecode::Image{};
  known_globals.clear();
  autos.clear();
  ever_run = false;
  program_error = vm::RunError::None;
  program_error_detail = 0;
  ++program_generation;
}

int32_t Controller::Impl::load_stored(std::string* error) {
  if (!has_stored) {
    if (error) *error = "no program has been downloaded";
    return kErrorNoStoredProgram;
  }
  unload();
  ram_image = stored_image;
  std::string why;
  bytecode::ImageView view;
  if (!bytecode::decode(ram_image.data(), ram_image.size(), ram_decoded, why) ||
      bytecode::load_image(ram_image.data(), ram_image.size(), view) != bytecode::LoadError::Ok) {
    if (error) *error = "stored program refused: " + why;
    unload();
    return kErrorStorage;
  }
  ram_memory.assign((vm::Machine::memory_needed(view, kProgramConfig) + 7) / 8, 0);
  machine = std::make_unique<vm::Machine>();
  const vm::LoadStatus s = machine->load(ram_image.data(), ram_image.size(), kProgramConfig,
                                         ram_memory.data(), ram_memory.size() * 8, *this);
  if (!s.ok()) {
    if (error) *error = "stored program refused by the loader";
    unload();
    return kErrorStorage;
  }
  known_globals = gold::known_globals(ram_decoded);
  autos.bind(machine->image());
  return 0;
}

int32_t Controller::Impl::start_program(uint32_t routine, const Value* args, uint32_t n) {
  autos.forget_activity();
  const vm::RunError e = machine->start(kProgramThread, routine, args, n);
  if (e != vm::RunError::None) return kErrorBadArguments;
  ever_run = true;
  program_error = vm::RunError::None;
  program_error_detail = 0;
  return 0;
}

int32_t Controller::Impl::execute_program(std::string_view name, const std::vector<double>& args) {
  if (!machine) return kErrorNoProgram;
  if (program_status() == 1) return kErrorProgramRunning;
  const int r = ram_decoded.find_routine(std::string(name));
  if (r < 0) return kErrorNoSuchEntry;
  const bytecode::Routine& routine = ram_decoded.routines[static_cast<size_t>(r)];
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
  if (machine->status(kProgramThread) != vm::ThreadStatus::Idle) machine->kill(kProgramThread);
  const int32_t code = start_program(static_cast<uint32_t>(r), values.data(),
                                     static_cast<uint32_t>(values.size()));
  if (code == 0) log("program started at " + std::string(name));
  return code;
}

int32_t Controller::Impl::program_status() const {
  if (!machine) return -2;
  if (!ever_run) return -1;
  switch (machine->status(kProgramThread)) {
    case vm::ThreadStatus::Running:
    case vm::ThreadStatus::Waiting: return 1;
    default: return 0;
  }
}

// --- Host ---

vm::CommandStatus Controller::Impl::read(uint32_t command, int32_t index, Value& out) {
  if (command == kMi || command == kPs || command == kEc) {
    if (index != 0) return gold::kErrorBadIndex;
    out = Value::of_int(command == kMi ? static_cast<int32_t>(autos.mask())
                        : command == kPs ? program_status() : ec);
    return vm::kCommandOk;
  }
  if (command > 0xFFFF) return gold::kErrorBadCommand;
  const int32_t r = drive_commands->read(static_cast<uint16_t>(command), index, out);
  return r == gold::kErrorNotHandledHere ? gold::kErrorNoValue : r;
}

vm::CommandStatus Controller::Impl::write(uint32_t command, int32_t index, Value value) {
  if (command == kMi) {
    if (index != 0) return gold::kErrorBadIndex;
    if (value.i < 0 || value.i > 65535) return gold::kErrorOutOfRange;
    autos.set_mask(static_cast<uint32_t>(value.i));
    return vm::kCommandOk;
  }
  if (command == kPs || command == kEc) return gold::kErrorReadOnly;
  if (command > 0xFFFF) return gold::kErrorBadCommand;
  const int32_t r = drive_commands->write(static_cast<uint16_t>(command), index, value);
  return r == gold::kErrorNotHandledHere ? gold::kErrorNotAssignable : r;
}

vm::CommandStatus Controller::Impl::execute(uint32_t command, int32_t index, const Value*, uint32_t) {
  if (command > 0xFFFF) return gold::kErrorBadCommand;
  const int32_t r = drive_commands->execute(static_cast<uint16_t>(command), index);
  // Program control from inside a program or a compiled line is not offered: the command line
  // handles XQ, HP, XC, KL, CC, LS, SV, LD, RS and DB as text (command_line.cpp).
  return r == gold::kErrorNotHandledHere ? gold::kErrorNoValue : r;
}

// --- the public face ---

Controller::Controller(ControllerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
Controller::~Controller() = default;
const std::vector<std::string>& Controller::boot_messages() const { return impl_->boot_messages; }
std::vector<Answer> Controller::send(std::string_view line) { return impl_->send(line); }
std::vector<Answer> Controller::query(std::string_view line) { return impl_->send(line, false); }
DownloadResult Controller::download(const std::vector<uint8_t>& bytes) { return impl_->download(bytes); }

bool Controller::download_source_file(const std::string& path, std::vector<Diagnostic>& diagnostics) {
  gold::CompileResult result = gold::compile_file(path);
  diagnostics = result.diagnostics;
  if (!result.ok()) return false;
  const DownloadResult r = impl_->download(bytecode::encode(result.image));
  if (!r.ok) {
    Diagnostic d;
    d.scheme = "image";
    d.message = r.error;
    d.where.file = path;
    diagnostics.push_back(d);
  }
  return r.ok;
}

bool Controller::load_stored_program(std::string* error) { return impl_->load_stored(error) == 0; }
int32_t Controller::execute_program(std::string_view name, const std::vector<double>& args) {
  return impl_->execute_program(name, args);
}
void Controller::advance(uint64_t duration_us) { impl_->advance(duration_us); }
uint64_t Controller::now_us() const { return impl_->now_us_; }
void Controller::set_input_level(int input, bool high) { impl_->axis->set_input_level(input, high); }
bool Controller::inject_fault(std::string_view name, bool persistent) {
  return impl_->axis->inject_fault(name, persistent);
}
drive::Axis& Controller::axis() { return *impl_->axis; }
int32_t Controller::program_status() const { return impl_->program_status(); }
int32_t Controller::program_error() const { return static_cast<int32_t>(impl_->program_error); }
std::string Controller::program_error_text() const {
  return impl_->program_error == vm::RunError::None ? std::string() : vm::run_error_text(impl_->program_error);
}
std::vector<LogEntry> Controller::take_log() {
  std::vector<LogEntry> out;
  out.swap(impl_->log_entries);
  return out;
}

}  // namespace uprog::controller
