// The D-series drive's firmware (pdl-drive.md): the stored program, one command per phase over
// tasks 1-3 (PhaseRoundRobin), the system variables and states mapped onto the axes, printl and
// run-time error events to every host, and the host protocol (host_lines.cpp). It is also the
// VM's Host for the program.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dialect/dl_lines.h"
#include "dialect/firmware.h"
#include "dialect/loaded_program.h"
#include "dialect/runtime.h"
#include "dialect/scheduling/phase_round_robin.h"
#include "dialect/semicolon_wire.h"
#include "dialects/pdl/debug_info.h"
#include "dialects/pdl/layout.h"
#include "vm/machine.h"

namespace uprog::pdl {

// The host protocol's error codes (pdl-drive.md, "Host protocol").
enum HostError : int32_t {
  kUnknownCommand = 1,
  kNoSuchVariable = 2,
  kBadIndex = 3,
  kReadOnly = 4,
  kBadValue = 5,
  kLevelTooLow = 6,
  kNoProgram = 7,
  kNoSuchLabel = 8,
  kBadTask = 9,
  kTaskBusy = 10,
  kServoNotReady = 11,
  kEnableRefused = 12,
};

// A user variable as the host sees it: from the image's globals and its "var" info lines.
struct HostVariable {
  std::string name;
  uint32_t global = 0;
  int32_t address = 0;
  uint32_t length = 1;
  char kind = 'l';  // 'l' long, 's' short, 'f' float, 'p' a pointer
  bool read_only = false;
  int32_t level_read = 0, level_write = 0;
};

class Firmware final : public dialect::Firmware, public vm::Host {
 public:
  Firmware(dialect::Runtime& runtime, const dialect::FirmwareOptions& options);

  // --- dialect::Firmware
  const dialect::WireForm& wire() const override { return wire_; }
  void boot(std::vector<std::string>& messages) override;
  uint64_t cycle_ns() const override { return uint64_t{phase_us_} * 1000; }
  void cycle(const std::vector<uint32_t>& drive_events) override;
  std::unique_ptr<dialect::Session> open_session() override;
  std::vector<dialect::Answer> query(std::string_view line) override;
  dialect::DownloadResult download(const std::vector<uint8_t>& bytes) override;
  std::string start(std::string_view entry) override;
  bool running() const override;
  int32_t program_error() const override { return last_error_; }
  std::string program_error_text() const override;
  std::string state_summary() const override;
  std::vector<dialect::ThreadInfo> threads() const override;

  // --- the debugger's hooks (debug_hooks.cpp)
  const dialect::LoadedProgram* loaded_program() const override { return program_.get(); }
  dialect::LoadedProgram* debug_program() override { return program_.get(); }
  void debug_runs(uint32_t thread) override { debugger_runs_ = thread; }
  dialect::Evaluation evaluate(uint32_t thread, uint32_t depth,
                               std::string_view expression) override;
  std::optional<std::vector<dialect::DebugFrame>> debug_frames(uint32_t thread) override;
  std::optional<uint32_t> debug_call_depth(uint32_t thread) override;
  std::optional<uint32_t> debug_function_entry(std::string_view name) override;
  dialect::Evaluation set_debug_local(uint32_t thread, uint32_t depth, std::string_view name,
                                      std::string_view value) override;

  // --- vm::Host
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override;
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override;
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t count) override;
  vm::CommandStatus message(uint32_t thread, uint32_t text, const Value* args,
                            uint32_t count) override;
  uint32_t now_us() override { return static_cast<uint32_t>(runtime_.now_ns() / 1000); }

  // --- the host protocol (host_lines.cpp): one host line with that host's level and download
  std::vector<dialect::Answer> host_line(std::string_view line, int32_t& level,
                                         dialect::DlReceiver* download, bool takes_time);
  uint32_t fclk() const { return fclk_; }

 private:
  void answer_one(std::string_view text, int32_t& level, dialect::DlReceiver* download,
                  std::vector<dialect::Answer>& answers);
  dialect::Answer read_name(std::string_view name, std::optional<int32_t> index, int32_t level);
  std::optional<dialect::Answer> write_name(std::string_view name, std::optional<int32_t> index,
                                            const std::vector<double>& values, int32_t level);
  std::optional<dialect::Answer> run_label(uint32_t task, std::string_view label);
  void reset_drive();
  // PDL's debug lines (debug_lines.cpp): stat, hold, cont and step for a task or all.
  bool debug_line(std::string_view text, std::vector<dialect::Answer>& answers);

  // A task's frame as walk_frames() finds it: a procedure's (fp its first word) or task code's.
  struct TaskFrame {
    const ProcInfo* proc = nullptr;
    uint32_t pc = 0;  // the code word of its line
    int32_t fp = 0;
  };
  std::vector<TaskFrame> walk_frames(uint32_t task) const;
  bool walk_routine_frame(uint32_t pc, uint32_t line_pc, int32_t sp, int32_t fp, int32_t base,
                          int32_t limit, std::vector<TaskFrame>& out) const;
  std::string frame_name(const TaskFrame& f) const;

  std::string verify(const std::vector<uint8_t>& bytes);
  bool load_stored(std::string* error);
  void start_reset_tasks();
  int32_t start_task(uint32_t task, uint32_t routine);
  vm::Machine* machine() { return program_ ? &program_->machine() : nullptr; }
  const vm::Machine* machine() const { return program_ ? &program_->machine() : nullptr; }
  int32_t task_state(uint32_t task) const;
  bool state_value(int32_t number) const;
  int32_t write_state(int32_t number, bool on, bool from_host);
  vm::CommandStatus write_variable(uint32_t id, int32_t index, int32_t v, bool from_host);
  vm::CommandStatus read_variable(uint32_t id, int32_t index, int32_t& v) const;
  void report_error(uint32_t task);
  drive::Axis* axis(int32_t index) const;

  dialect::Runtime& runtime_;
  dialect::SemicolonWire wire_;
  scheduling::PhaseRoundRobin schedule_;
  uint32_t debugger_runs_ = scheduling::kNoThread;  // debug_runs()
  uint32_t phase_us_ = 50;
  std::optional<std::vector<uint8_t>> stored_;
  bool flash_read_ = false;
  std::unique_ptr<dialect::LoadedProgram> program_;
  std::vector<HostVariable> variables_;
  uint32_t fclk_ = 0;
  int32_t task_error_[kTasks + 1] = {};     // the run-time error that stopped each task
  uint32_t task_routine_[kTasks + 1] = {};  // where a host's run started it
  bool kill_pending_[kTasks + 1] = {};
  bool homed_ = false;
  int32_t in_func_[7] = {0, 9, 11, 17, 7, 7, 7};
  // A program's change to a state the drive refreshes lasts until the next phase (2.4.3).
  struct Override {
    int32_t number = -1;
    bool value = false;
  };
  std::vector<Override> overrides_;
  int32_t last_error_ = 0;
  DebugInfo debug_info_;  // the loaded program's (debug_info.h)
};

}  // namespace uprog::pdl
