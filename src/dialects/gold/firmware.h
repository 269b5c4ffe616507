// The Gold drive's firmware (dialect::Firmware): the stored program and the one in RAM, the
// Gold command line and its program control, auto-routines, EC, and the background slice that
// runs the program after every servo cycle. It is also the VM's Host for the program and the
// command line's tiny images.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dialect/dl_lines.h"
#include "dialect/firmware.h"
#include "dialect/loaded_program.h"
#include "dialect/runtime.h"
#include "dialects/gold/auto_routines.h"
#include "dialects/gold/compile.h"
#include "dialects/gold/drive_commands.h"
#include "dialects/gold/elmo_wire.h"
#include "dialects/gold/interpreter_errors.h"
#include "dialects/gold/recorder_signals.h"
#include "vm/machine.h"

namespace uprog::gold {

constexpr uint32_t kProgramThread = 0;
constexpr uint32_t kMaxBackgroundUs = 1'000'000;  // the longest background pass one may fix

// How the Gold command line splits a host line into expressions (manual 1.1): at `;`, CR and LF,
// `**` to the end of the line a comment, 511 characters an expression. The wire's framing too.
dialect::FramerOptions command_line_framing();

class Firmware final : public dialect::Firmware, public vm::Host {
 public:
  Firmware(dialect::Runtime& runtime, const dialect::FirmwareOptions& options);

  // --- dialect::Firmware ---
  const dialect::WireForm& wire() const override { return wire_; }
  void boot(std::vector<std::string>& messages) override;
  uint64_t cycle_ns() const override;  // a background pass (background_cycle.h)
  bool world_directive(std::string_view name, std::string_view arg, std::string& failure) override;
  void cycle(const std::vector<uint32_t>& drive_events) override;
  std::unique_ptr<dialect::Session> open_session() override;
  std::vector<dialect::Answer> query(std::string_view line) override { return send(line, false); }
  dialect::DownloadResult download(const std::vector<uint8_t>& bytes) override;
  std::string start(std::string_view entry) override;
  bool running() const override { return program_status() == 1; }
  int32_t program_error() const override { return static_cast<int32_t>(program_error_); }
  std::string program_error_text() const override;
  std::string state_summary() const override;
  std::vector<dialect::ThreadInfo> threads() const override;
  const dialect::LoadedProgram* loaded_program() const override { return program_.get(); }
  std::optional<drive::Signal> recorder_signal(std::string_view n) const override {
    return gold::recorder_signal(n);
  }
  dialect::LoadedProgram* debug_program() override { return program_.get(); }
  dialect::Evaluation evaluate(uint32_t thread, uint32_t depth,
                               std::string_view expression) override;  // debug_hooks.cpp
  std::string start_with_arguments(std::string_view entry,
                                   const std::vector<double>& args) override;

  // --- vm::Host: drive commands, plus MI, PS and EC that the firmware keeps ---
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override;
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override;
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t arg_count) override;
  uint32_t now_us() override { return static_cast<uint32_t>(runtime_.now_ns() / 1000); }

  // --- the command line (command_line.cpp, program_control.cpp): one host line, its
  // expressions each taking a servo cycle when `takes_time` ---
  std::vector<dialect::Answer> send(std::string_view line, bool takes_time = true);
  // As send(), with the DL commands of one host's download (a Session's).
  std::vector<dialect::Answer> send_line(std::string_view line, bool takes_time,
                                         dialect::DlReceiver* download);
  // Lets one servo cycle pass: an expression's time (docs/dialects/gold-command-line.md).
  void spend_expression_time();
  uint64_t servo_cycle_ns() const;  // TS

 private:
  // --- the program store and RAM (firmware.cpp) ---
  dialect::DownloadResult verify(const std::vector<uint8_t>& bytes);
  int32_t load_stored(std::string* error);  // CC
  void unload();
  void forget_recorder_variables();  // 2.16: DB##RV[n] mappings end with a download
  int32_t start_program(uint32_t routine, const Value* args, uint32_t n);
  int32_t execute_program(std::string_view name, const std::vector<double>& args);
  int32_t program_status() const;
  vm::Machine* machine() { return program_ ? &program_->machine() : nullptr; }
  void log(std::string text) { runtime_.log(std::move(text)); }

  // --- the background (background.cpp) ---
  void background_slice();
  void raise_auto_events(uint32_t drive_events);
  // --- the Elmo debugger's commands, DB##BP, BC, GO, SO, SI, SU, MS, PS, ES (debug_commands.cpp)
  // ---
  bool debug_command(const std::string& word, std::vector<dialect::Answer>& answers);
  void after_debug_slice(vm::SliceEnd end);
  void dispatch_auto_routines();
  void on_run_time_error();

  // --- the command line ---
  void download_expression(std::string_view expression, dialect::DlReceiver& download,
                           std::vector<dialect::Answer>& answers);
  void expression(std::string_view text, std::vector<dialect::Answer>& answers);
  void recorder_upload(std::string_view argument, std::vector<dialect::Answer>& answers);  // BH=n
  bool program_control(const std::string& text, std::vector<dialect::Answer>& answers);
  void run_line(const std::string& text, std::vector<dialect::Answer>& answers);
  // Binds the machine of a host line or a debugger expression, whose first globals are the
  // program's in the same order, to the program's own words (Machine::bind_global): it reads and
  // assigns them in place, without copying every global in and out. A program unloaded while
  // such a machine runs is kept until it ends (retire_running_program).
  void bind_program_globals(vm::Machine& line);
  // Runs `line` for at most `budget` instructions with the program's globals bound.
  vm::SliceResult run_bound(vm::Machine& line, uint64_t budget);
  dialect::Answer error_answer(int32_t code, std::string why);
  int32_t save_parameters();
  int32_t load_parameters();
  void reset_drive();
  std::vector<std::string> listing() const;
  int32_t map_recorder(const std::string& text);

  dialect::Runtime& runtime_;
  dialect::FirmwareOptions options_;
  ElmoWire wire_;
  scheduling::WholeLines schedule_;
  vm::Budget slice_budget_;      // the whole-lines policy's, worked out once
  uint32_t background_us_ = 0;   // a fixed background pass, µs; 0: from TS (background_cycle.h)
  drive::Axis* axis_ = nullptr;  // the runtime's axis since the last boot
  std::unique_ptr<DriveCommands> drive_commands_;

  // The stored program (the drive's flash, mirrored) and the one in RAM.
  std::optional<std::vector<uint8_t>> stored_;
  bool flash_read_ = false;
  std::unique_ptr<dialect::LoadedProgram> program_;  // null without a program in RAM
  std::vector<KnownGlobal> known_globals_;
  bool ever_run_ = false;
  uint32_t program_generation_ = 0;  // bumped whenever RAM gets another program
  // The program unloaded while a host line or an expression bound to its globals ran: kept until
  // that machine ends, so that its stores never reach freed words.
  std::unique_ptr<dialect::LoadedProgram> retired_program_;
  bool bound_line_running_ = false;
  vm::RunError program_error_ = vm::RunError::None;
  int32_t program_error_detail_ = 0;
  AutoRoutines autos_;

  int32_t ec_ = 0;                               // EC: the interpreter's last error code
  std::map<int32_t, std::string> recorder_map_;  // DB##RV[n]=name

  // The Elmo debugger's breakpoints (a code word, and the hit that stops: DB##BP=pc,n) and step.
  struct DebugBreakpoint {
    uint32_t pc;
    int32_t stop_at_hit;
    int32_t hits;
  };
  enum class DebugStep : uint8_t { None, Over, In, Out };
  std::vector<DebugBreakpoint> debug_breakpoints_;
  DebugStep debug_step_ = DebugStep::None;
  uint32_t debug_step_depth_ = 0;
  bool debug_active_ = false;  // breakpoints or a step: the background looks after each slice
  bool debug_error_reported_ = false;  // DB##ES has read the last run-time error
  uint32_t debug_generation_ = 0;      // the program they belong to (program_generation_)
  void forget_debug_state_of_another_program();
};

}  // namespace uprog::gold
