// The drive: axes, flash, virtual time and the firmware's cycle (controller.h). The Drive is the
// Runtime the firmware borrows; each of its parts has one owner.
#include "controller/controller.h"

#include <algorithm>
#include <functional>

#include "controller/flash.h"
#include "drive/axis.h"
#include "drive/parameter_store.h"

namespace uprog::controller {
namespace {

constexpr std::string_view kParametersRecord = "parameters.txt";

std::span<const uint8_t> bytes_of(const std::string& text) {
  return {reinterpret_cast<const uint8_t*>(text.data()), text.size()};
}

}  // namespace

class Controller::Drive final : public dialect::Runtime, public drive::ProgramWords {
 public:
  explicit Drive(ControllerOptions options)
      : options_(std::move(options)), flash_(options_.state_dir) {
    dialect::FirmwareOptions firmware_options;
    firmware_options.timing = options_.timing;
    firmware_options.safe_boot = options_.safe_boot;
    firmware_options.wire_style = options_.wire_style;
    firmware_ = options_.dialect->make_firmware(*this, firmware_options);
    reboot();
    console_ = firmware_->open_session();
  }

  // --- dialect::Runtime ---
  std::size_t axis_count() const override { return axes_.size(); }
  drive::Axis& axis(std::size_t index) override { return *axes_.at(index); }
  dialect::Flash& flash() override { return flash_; }
  uint64_t now_ns() const override { return now_ns_; }
  // A host line's time (dialect::Runtime): none while the debugger holds the program.
  void advance_ns(uint64_t ns) override {
    if (lines_take_time_) advance_by(ns);
  }
  void advance_by(uint64_t ns);
  // From the time given so far to the firmware's next cycle (0 when a reboot made it due already:
  // run_until() then runs it).
  uint64_t until_next_cycle_ns() const {
    return next_cycle_ns_ > target_ns_ ? next_cycle_ns_ - target_ns_ : 0;
  }
  void log(std::string text) override { log_.push_back({now_ns_ / 1000, std::move(text)}); }
  void output(std::string_view text) override { output_.emplace_back(text); }
  void reboot() override;
  bool save_axis_parameters(std::string* error) override {
    return flash_.write(kParametersRecord,
                        bytes_of(drive::serialize_parameters(axis(0).parameters())), error);
  }
  std::optional<drive::Parameters> saved_axis_parameters(std::string* error) override;

  // --- drive::ProgramWords: the program in RAM, for the recorder's global channels ---
  std::optional<Word> find_global(std::string_view name, uint32_t element) const override;
  std::span<const Value> memory() const override;

  const ControllerOptions options_;
  StateFlash flash_;
  std::vector<std::unique_ptr<drive::Axis>> axes_;
  std::unique_ptr<dialect::Firmware> firmware_;
  std::unique_ptr<dialect::Session> console_;  // the drive's own session: send() and transcripts
  std::vector<std::string> boot_messages_;
  std::vector<LogEntry> log_;
  std::vector<std::string> output_;
  bool lines_take_time_ = true;

 private:
  void run_until(uint64_t target_ns);
  void run_one_axis_until(uint64_t target_ns);
  uint64_t axis_period_ns(size_t a) const {
    return uint64_t{std::max(axes_[a]->period_us(), 1u)} * 1000;
  }
  // A firmware's cycle of at least a microsecond: time always moves on.
  uint64_t cycle_ns() const { return std::max<uint64_t>(firmware_->cycle_ns(), 1000); }

  uint64_t now_ns_ = 0;
  uint64_t target_ns_ = 0;  // all the time given to advance_ns(), a part of a cycle included
  std::vector<uint64_t> next_step_ns_;  // per axis, when its next servo cycle is due
  uint64_t next_cycle_ns_ = 0;          // when the firmware's next cycle is due
  std::vector<uint32_t> events_;        // per axis, its event bits since the firmware's last cycle
};

// A reset makes fresh axes; the world outside them (inputs, switches, the index pulse) stays.
void Controller::Drive::reboot() {
  std::vector<drive::Axis::World> world;
  for (const auto& axis : axes_) world.push_back(axis->world());
  axes_.clear();
  for (uint32_t a = 0; a < std::clamp(options_.axes, 1u, kMaxAxes); ++a) {
    axes_.push_back(std::make_unique<drive::Axis>());
    axes_.back()->recorder().set_program_words(this);
  }
  events_.assign(axes_.size(), 0);
  std::string error;
  if (auto params = saved_axis_parameters(&error)) {
    axes_[0]->load_parameters(*params);
  } else if (!error.empty()) {
    boot_messages_.push_back("saved parameters refused: " + error + "; using defaults");
  }
  if (options_.servo_period_us != 0) {
    for (auto& axis : axes_) axis->set_period_us(static_cast<int32_t>(options_.servo_period_us));
  }
  for (size_t a = 0; a < std::min(world.size(), axes_.size()); ++a) axes_[a]->place_world(world[a]);
  firmware_->boot(boot_messages_);
  next_cycle_ns_ = now_ns_ + cycle_ns();
  next_step_ns_.resize(axes_.size());
  for (size_t a = 0; a < axes_.size(); ++a) next_step_ns_[a] = now_ns_ + axis_period_ns(a);
}

std::optional<drive::Parameters> Controller::Drive::saved_axis_parameters(std::string* error) {
  const auto bytes = flash_.read(kParametersRecord, error);
  if (!bytes) return std::nullopt;
  return drive::parse_parameters(std::string(bytes->begin(), bytes->end()), error);
}

std::optional<drive::ProgramWords::Word> Controller::Drive::find_global(std::string_view name,
                                                                        uint32_t element) const {
  const dialect::LoadedProgram* program = firmware_->loaded_program();
  if (program == nullptr) return std::nullopt;
  const int g = program->image().find_global(std::string(name));
  if (g < 0) return std::nullopt;
  const std::span<const Value> words = program->machine().global_words(static_cast<uint32_t>(g));
  const std::span<const Value> memory = program->machine().memory();
  if (element >= words.size()) return std::nullopt;
  Word word;
  word.is_float = program->image().globals[static_cast<size_t>(g)].type == ValueType::Float;
  // A global in the data memory is read by its address there (a new program brings a new memory);
  // one the firmware binds elsewhere, where it lives.
  const std::less<const Value*> before;  // pointers into different objects compare only so
  if (!before(words.data(), memory.data()) && before(words.data(), memory.data() + memory.size()))
    word.address = static_cast<uint32_t>(words.data() - memory.data()) + element;
  else
    word.bound = words.data() + element;
  return word;
}

std::span<const Value> Controller::Drive::memory() const {
  const dialect::LoadedProgram* program = firmware_->loaded_program();
  return program != nullptr ? program->machine().memory() : std::span<const Value>{};
}

void Controller::Drive::advance_by(uint64_t ns) {
  target_ns_ += ns;
  run_until(target_ns_);
}

// Whatever is due next happens next: an axis's servo cycle, the firmware's cycle, or both at the
// same instant, the axes first. A period is read after the cycle it follows, so a TS changed in
// a cycle counts from the next one.
void Controller::Drive::run_until(uint64_t target_ns) {
  if (axes_.size() == 1) return run_one_axis_until(target_ns);
  const size_t axes = axes_.size();
  for (;;) {
    uint64_t next = next_cycle_ns_;
    for (size_t a = 0; a < axes; ++a) next = std::min(next, next_step_ns_[a]);
    if (next > target_ns) return;
    now_ns_ = next;
    for (size_t a = 0; a < axes; ++a) {
      if (next_step_ns_[a] == next) events_[a] |= axes_[a]->step();
    }
    if (next_cycle_ns_ == next) {
      firmware_->cycle(events_);
      for (uint32_t& e : events_) e = 0;
      next_cycle_ns_ = next + cycle_ns();
    }
    for (size_t a = 0; a < axes; ++a) {
      if (next_step_ns_[a] == next) next_step_ns_[a] = next + axis_period_ns(a);
    }
  }
}

// The same with one axis, the usual drive: this loop runs every servo cycle, so it keeps what
// it touches in locals.
void Controller::Drive::run_one_axis_until(uint64_t target_ns) {
  drive::Axis& axis = *axes_[0];
  uint64_t step_due = next_step_ns_[0];
  for (;;) {
    const uint64_t next = std::min(next_cycle_ns_, step_due);
    if (next > target_ns) break;
    now_ns_ = next;
    const bool steps = step_due == next;
    if (steps) events_[0] |= axis.step();
    if (next_cycle_ns_ == next) {
      firmware_->cycle(events_);
      events_[0] = 0;
      next_cycle_ns_ = next + cycle_ns();
    }
    if (steps) step_due = next + axis_period_ns(0);
  }
  next_step_ns_[0] = step_due;
}

// --- the public face ---

Controller::Controller(ControllerOptions options)
    : drive_(std::make_unique<Drive>(std::move(options))) {}
Controller::~Controller() = default;

const dialect::Dialect& Controller::dialect() const { return *drive_->options_.dialect; }
dialect::Firmware& Controller::firmware() { return *drive_->firmware_; }
const std::vector<std::string>& Controller::boot_messages() const { return drive_->boot_messages_; }

std::vector<Answer> Controller::send(std::string_view line) { return drive_->console_->send(line); }
std::vector<Answer> Controller::query(std::string_view line) {
  return drive_->firmware_->query(line);
}
std::unique_ptr<dialect::Session> Controller::open_session() {
  return drive_->firmware_->open_session();
}

DownloadResult Controller::download(const std::vector<uint8_t>& stored_form) {
  return drive_->firmware_->download(stored_form);
}

bool Controller::download_source_file(const std::string& path,
                                      std::vector<Diagnostic>& diagnostics) {
  dialect::CompileOutput out = dialect().compile_file(path, {});
  const bool compiled = out.ok();  // before its diagnostics move out
  diagnostics = std::move(out.diagnostics);
  if (!compiled) return false;
  const DownloadResult r = download(out.stored_form);
  if (r.ok && !out.debug_map.empty()) firmware().set_debug_map(out.debug_map);
  if (!r.ok) {
    Diagnostic d;
    d.scheme = "image";
    d.message = r.error;
    d.where.file = path;
    diagnostics.push_back(d);
  }
  return r.ok;
}

std::string Controller::start_program(std::string_view entry) {
  return drive_->firmware_->start(entry);
}
void Controller::reboot() { drive_->reboot(); }

void Controller::advance(uint64_t duration_us) { drive_->advance_by(duration_us * 1000); }
void Controller::advance_ns(uint64_t duration_ns) { drive_->advance_by(duration_ns); }
void Controller::set_lines_take_time(bool on) { drive_->lines_take_time_ = on; }
uint64_t Controller::ns_to_next_cycle() const { return drive_->until_next_cycle_ns(); }
uint64_t Controller::now_us() const { return drive_->now_ns() / 1000; }
uint64_t Controller::now_ns() const { return drive_->now_ns(); }
void Controller::set_input_level(int input, bool high) {
  drive_->axis(0).set_input_level(input, high);
}
bool Controller::inject_fault(std::string_view name, bool persistent) {
  return drive_->axis(0).inject_fault(name, persistent);
}
drive::Axis& Controller::axis() { return drive_->axis(0); }
drive::Recorder& Controller::recorder() { return drive_->axis(0).recorder(); }

std::optional<drive::Channel> Controller::recorder_channel(std::string_view name,
                                                           std::string* why) {
  if (const std::optional<drive::Signal> s = drive_->firmware_->recorder_signal(name)) {
    return drive::signal_channel(*s, std::string(name));
  }
  if (const drive::SignalInfo* info = drive::find_signal(name))
    return drive::signal_channel(info->signal, std::string(name));
  if (const auto word = drive_->firmware_->recorder_word(name))
    return drive::word_channel(*word, std::string(name));
  return drive::global_channel(*drive_, name, why);
}

bool Controller::program_running() const { return drive_->firmware_->running(); }
int32_t Controller::program_error() const { return drive_->firmware_->program_error(); }
std::string Controller::program_error_text() const {
  return drive_->firmware_->program_error_text();
}

std::vector<LogEntry> Controller::take_log() {
  std::vector<LogEntry> out;
  out.swap(drive_->log_);
  return out;
}

std::vector<std::string> Controller::take_output() {
  std::vector<std::string> out;
  out.swap(drive_->output_);
  return out;
}

}  // namespace uprog::controller
