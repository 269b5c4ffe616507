// The Controller's state and its Host for the VM (private to src/controller). One program
// machine runs the loaded image on thread 0; command lines run on machines of their own.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "controller/auto_routines.h"
#include "controller/controller.h"
#include "dialects/gold/compile.h"
#include "dialects/gold/drive_commands.h"
#include "drive/axis.h"
#include "vm/machine.h"

namespace uprog::controller {

// Interpreter error codes the controller adds to the drive's (docs/dialects/gold-command-line.md).
enum ControllerError : int32_t {
  kErrorSyntax = 19,              // the expression does not compile (manual 1.3.2 "Command syntax error")
  kErrorNoProgram = 201,          // no program in RAM
  kErrorNoSuchEntry = 202,        // XQ## names no function, label or auto-routine
  kErrorProgramRunning = 203,     // XQ/CC while the program runs
  kErrorNotHalted = 204,          // XC while the program is not halted
  kErrorBadArguments = 205,       // XQ##f(...) with the wrong number or form of arguments
  kErrorStorage = 206,            // SV/LD/CC could not read or write the state directory
  kErrorNoStoredProgram = 207,    // CC with nothing downloaded
  kErrorLineDidNotFinish = 208,   // a command line waited or ran too long
  kErrorNoSuchVariable = 209,     // DB##RV[n]=name with an unknown name
  kErrorRunTimeBase = 100,        // 100 + vm::RunError for a run-time error of a line
};

constexpr uint32_t kProgramThread = 0;

struct Controller::Impl final : vm::Host {
  explicit Impl(ControllerOptions options);

  // vm::Host: drive commands, plus MI, PS and EC that the controller keeps.
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override;
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override;
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t arg_count) override;
  uint32_t now_us() override { return static_cast<uint32_t>(now_us_); }

  // --- lifecycle (controller.cpp) ---
  void boot();  // power-up and RS
  DownloadResult verify(const std::vector<uint8_t>& bytes, bytecode::Image* decoded);
  DownloadResult download(const std::vector<uint8_t>& bytes);
  int32_t load_stored(std::string* error);  // CC
  void unload();
  int32_t start_program(uint32_t routine, const Value* args, uint32_t n);
  int32_t execute_program(std::string_view name, const std::vector<double>& args);
  int32_t program_status() const;
  void log(std::string text);

  // --- time (scheduler.cpp) ---
  void advance(uint64_t duration_us);
  void servo_cycle();
  void background_slice();
  void dispatch_auto_routines();
  void on_run_time_error();
  std::string where(uint32_t pc) const;

  // --- the command line (command_line.cpp, program_control.cpp) ---
  std::vector<Answer> send(std::string_view text, bool takes_time = true);
  void expression(const std::string& text, std::vector<Answer>& answers);
  bool program_control(const std::string& text, std::vector<Answer>& answers);
  void run_line(const std::string& text, std::vector<Answer>& answers);
  Answer error_answer(int32_t code, std::string why);
  int32_t save_parameters();
  int32_t load_parameters();
  void reset_drive();
  std::vector<std::string> listing() const;
  int32_t map_recorder(const std::string& text);

  ControllerOptions options;
  std::vector<std::string> boot_messages;
  std::vector<LogEntry> log_entries;
  uint64_t now_us_ = 0;
  uint64_t residual_us = 0;  // time given to advance() but short of a whole servo cycle

  std::unique_ptr<drive::Axis> axis;
  std::unique_ptr<gold::DriveCommands> drive_commands;
  std::optional<std::string> saved_parameters;  // SV without a state directory

  // The stored program (the drive's flash) and the one in RAM.
  std::vector<uint8_t> stored_image;
  bool has_stored = false;
  std::vector<uint8_t> ram_image;
  bytecode::Image ram_decoded;
  std::vector<uint64_t> ram_memory;
  std::unique_ptr<vm::Machine> machine;  // null without a program in RAM
  std::vector<gold::KnownGlobal> known_globals;
  bool ever_run = false;
  uint32_t program_generation = 0;  // bumped whenever RAM gets another program
  vm::RunError program_error = vm::RunError::None;
  int32_t program_error_detail = 0;
  AutoRoutines autos;

  int32_t ec = 0;  // EC: the interpreter's last error code
  std::map<int32_t, std::string> recorder_map;  // DB##RV[n]=name
};

}  // namespace uprog::controller
