// The simulated drive: the axes, the flash, virtual time and the connections of one drive, with a
// dialect's firmware (dialect::Firmware) running the program and answering the command line.
// It names no dialect: the tools pick one from the registry and hand it over in the options.
// Transports, transcripts and `uprog run` drive a drive only through this class.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/dialect.h"
#include "drive/recorder.h"
#include "support/diagnostic.h"

namespace uprog::drive {
class Axis;
}

namespace uprog::controller {

using dialect::Answer;
using dialect::DownloadResult;
using dialect::LogEntry;
using dialect::Timing;

constexpr uint32_t kMaxAxes = 4;

struct ControllerOptions {
  const dialect::Dialect* dialect = nullptr;  // required: whose firmware the drive runs
  // Holds the flash's records (the stored program, saved parameters). Empty: nothing persists,
  // the records live in memory.
  std::string state_dir;
  bool safe_boot = false;  // boot without starting the program
  Timing timing;
  dialect::WireStyle wire_style = dialect::WireStyle::kDrive;  // what the transports speak
  // The drive's axes, 1..4: the first keeps the saved parameters, the others start from the
  // defaults (a transcript's `drive axes=N`).
  uint32_t axes = 1;
  // Every axis's servo period in µs, 25..2000, over the saved one; 0 keeps it (`phase_us=N`).
  uint32_t servo_period_us = 0;
};

class Controller {
 public:
  // Boots: fresh axes with the saved parameters, then the firmware's boot (the stored program,
  // refused with a message in boot_messages() when corrupt or foreign).
  explicit Controller(ControllerOptions options);
  ~Controller();
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  const dialect::Dialect& dialect() const;
  dialect::Firmware& firmware();
  // What boot (or a reboot) reported: a refused stored program, unreadable parameters.
  const std::vector<std::string>& boot_messages() const;

  // --- the host side ---
  // One host line on the drive's own console session: the answers in order; it takes the
  // virtual time the firmware's line handling takes.
  std::vector<Answer> send(std::string_view line);
  // As send(), but taking no virtual time: for recorders and tools that sample the drive.
  std::vector<Answer> query(std::string_view line);
  // A host's own conversation (its download state): one per connection.
  std::unique_ptr<dialect::Session> open_session();

  // Stores a program's stored form, checked first; a refused one leaves the stored program.
  DownloadResult download(const std::vector<uint8_t>& stored_form);
  // Compiles a source file with the drive's dialect and downloads it; false with diagnostics.
  bool download_source_file(const std::string& path, std::vector<Diagnostic>& diagnostics);
  // Loads the stored program and starts it as `uprog run` does; "" or why not.
  std::string start_program(std::string_view entry = {});
  // Starts the drive again as at power-up: fresh axes with the saved parameters, the stored
  // program loaded and started as the dialect starts it then (unless safe boot).
  void reboot();

  // --- time and the world ---
  // Lets virtual time pass: the axes step on their servo periods, the firmware's cycle on its.
  void advance(uint64_t duration_us);
  void advance_ns(uint64_t duration_ns);
  // How long until the firmware's next cycle: advance_ns() by it runs that cycle and no more (the
  // debugger: a program that stops in that cycle stops with time standing at it).
  uint64_t ns_to_next_cycle() const;
  // Off while a debugger holds the program: the hosts' lines take no virtual time, so nothing
  // moves while it stands still (on again when it runs).
  void set_lines_take_time(bool on);
  uint64_t now_us() const;
  uint64_t now_ns() const;
  void set_input_level(int input, bool high);
  // Latches a drive fault by name (drive/faults.h); false when the name is unknown.
  bool inject_fault(std::string_view name, bool persistent = false);
  drive::Axis& axis();
  // The first axis's recorder, and a channel for it by name: the dialect's name of a signal
  // (Gold's PX), a neutral one (drive/recorder.h), or a global of the program ("cnt", "arr[2]").
  drive::Recorder& recorder();
  std::optional<drive::Channel> recorder_channel(std::string_view name, std::string* why);

  // --- state ---
  bool program_running() const;
  int32_t program_error() const;  // last run-time error of the program (vm RunError), 0 none
  std::string program_error_text() const;  // "" when none
  // Notable events since the last call (auto-routines entered, run-time errors, boot).
  std::vector<LogEntry> take_log();
  // What the drive sent on its own since the last call, a text each (printl, PRINTF, boot).
  std::vector<std::string> take_output();

 private:
  class Drive;
  std::unique_ptr<Drive> drive_;
};

}  // namespace uprog::controller
