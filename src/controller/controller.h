// The simulated drive's firmware: one axis, one VM running the stored user program, the Gold
// command line, auto-routine dispatch and persistence, all in deterministic virtual time.
// Transports, `uprog transcript` and `uprog run` drive a drive only through this class.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "support/diagnostic.h"

namespace uprog::drive {
class Axis;
}

namespace uprog::controller {

// How much of the user program runs in each background slice (docs/controller.md).
struct Timing {
  // Whole source lines the program runs per servo cycle (manual 2.2: one line per background
  // slice; the background runs once per servo cycle here).
  uint32_t lines_per_cycle = 1;
  // The program runs until it waits, yields or ends: only waits advance time (CI, benchmarks).
  bool unlimited = false;
  // Guard for `unlimited`: a slice stops after this many source lines even without a wait, so
  // a busy loop cannot hang the simulation (it continues in the next cycle). Lines, not
  // instructions: every loop iteration and every call of a compiled program ends a line, and a
  // line budget costs the VM nothing per instruction.
  uint64_t unlimited_line_cap = 1'000'000;
  // Every slice also stops after this many jumps back (vm::Budget::back_jumps): a downloaded
  // image whose loop never ends a line (hand-made; compiled Gold always ends one) cannot hang
  // the drive. Compiled programs meet their line budget long before.
  uint64_t back_jump_cap = 1'000'000;
};

struct ControllerOptions {
  // Holds program.upi (the stored program) and parameters.txt (SV). Empty: nothing persists,
  // SV/LD keep the saved parameters in memory.
  std::string state_dir;
  bool safe_boot = false;  // boot without running AUTOEXEC
  Timing timing;
};

// One answer of the command line: a value, or an error with the interpreter's code (EC).
struct Answer {
  std::string text;     // "7", "3.600000", or for an error "Error: <why>"
  int32_t error = 0;    // 0 for a value; else the EC code (docs/dialects/gold-command-line.md)
  bool is_error() const { return error != 0; }
};

// Something the firmware did on its own, for `uprog run` and debuggers.
struct LogEntry {
  uint64_t time_us;
  std::string text;  // "auto-routine AUTO_I1 entered", "run-time error 1 (division by zero) at ..."
};

// The result of giving the drive an image.
struct DownloadResult {
  bool ok = false;
  std::string error;  // why the image was refused; the stored program is then unchanged
  bool storage_failed = false;  // the image was sound, but the state directory could not take it
};

class Controller {
 public:
  // Boots: loads saved parameters and the stored program from `state_dir` (refusing a corrupt
  // or foreign one with a message in boot_messages()), then runs AUTOEXEC unless safe_boot.
  explicit Controller(ControllerOptions options = {});
  ~Controller();
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  // What boot (or RS) reported: refused stored image, unreadable parameters.
  const std::vector<std::string>& boot_messages() const;

  // --- the host side ---
  // One host line: expressions separated by ';', CR or LF; "**" starts a comment. Returns one
  // answer per expression that shows a value or fails, in order. Each expression takes one
  // servo cycle of virtual time (the drive answers from its background loop).
  std::vector<Answer> send(std::string_view line);
  // As send(), but takes no virtual time: for recorders and tools that sample the drive.
  std::vector<Answer> query(std::string_view line);

  // Stores an image (verified first: CRC, format, verifier). Does not load it into RAM: `CC`
  // (or load_stored_program()) does. A refused image leaves the stored program intact.
  DownloadResult download(const std::vector<uint8_t>& image_bytes);
  // Compiles a Gold source file and downloads it; false with diagnostics on compile errors.
  bool download_source_file(const std::string& path, std::vector<Diagnostic>& diagnostics);
  // CC: loads the stored program into RAM (PS becomes -1). False when there is none.
  bool load_stored_program(std::string* error = nullptr);
  // XQ##name(args): starts the program at a function, label or auto-routine. 0 or an EC code.
  int32_t execute_program(std::string_view name, const std::vector<double>& args = {});

  // --- time and the world ---
  // Runs servo cycles (TS each) for `duration_us`, each followed by a background slice.
  void advance(uint64_t duration_us);
  uint64_t now_us() const;
  void set_input_level(int input, bool high);
  // Latches a drive fault by name (drive/faults.h); false when the name is unknown.
  bool inject_fault(std::string_view name, bool persistent = false);
  drive::Axis& axis();

  // --- state ---
  int32_t program_status() const;          // PS: -2, -1, 0, 1
  int32_t program_error() const;           // last run-time error of the program (vm RunError), 0 none
  std::string program_error_text() const;  // "" when none
  // Notable events since the last call (auto-routines entered, run-time errors, boot).
  std::vector<LogEntry> take_log();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace uprog::controller
