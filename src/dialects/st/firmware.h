// The S300 drive's firmware (dialect::Firmware): the stored source, compiled by the drive at boot
// and on PLCRUN/PLCSTART with the MSG=2 report; the PLC programs in cyclic tasks in virtual time
// (scheduling::CyclicTasks); F31/F32; the ASCII command line (command_line.cpp) with motion
// tasks (motion.cpp) on the simulated axis; the VM's Host for XREAD/XWRITE/COMMAND/PRINTF.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dialect/firmware.h"
#include "dialect/loaded_program.h"
#include "dialect/runtime.h"
#include "dialect/scheduling/cyclic_tasks.h"
#include "dialects/st/ascii_table.h"
#include "dialects/st/compile.h"
#include "dialects/st/wire.h"
#include "vm/machine.h"

namespace uprog::st {

// The error codes of the ASCII interface (`ERR code text`).
enum AsciiError : int32_t {
  kErrUnknown = 1,
  kErrSyntax = 2,
  kErrRange = 3,
  kErrReadOnly = 4,
  kErrNeedsDisabled = 5,
  kErrNeedsEnabled = 6,
  kErrOpmode = 7,
  kErrFault = 8,
  kErrTask = 9,
  kErrStorage = 10,
  kErrCompileFailed = 11,
  // The download's (session.cpp), as Gold's 210–213: PLCDL hex or END without BEGIN, a bad
  // size (BEGIN's, or END before all bytes), bad data (not hex pairs, more than announced).
  kErrNoDownload = 12,
  kErrDownloadSize = 13,
  kErrDownloadData = 14,
  // The debug commands' own:
  kErrNotHeld = 16,
  kErrPlcStopped = 17,
};

// PLCSTAT, PLCHOLD, PLCCONT, PLCSTEP (debug_commands.cpp): their argument is a program's name.
bool is_debug_command(std::string_view name);

constexpr uint64_t kStepNs = 125'000;  // the axis steps every 125 µs, two 62.5 µs ticks
constexpr size_t kMaxStoredSource = 61'440;
constexpr int32_t kModeReference = 12;  // INxMODE 12: the input is the reference switch

// A motion task (ORDER): target, speed, control word, ramps, next task and its delay.
struct MotionTask {
  int32_t p = 0, v = 0, c = 0, acc = 10, dec = 10, a2 = 0, d2 = 0, fn = 0, ft = 0;
  bool defined = false;
};

class Firmware final : public dialect::Firmware, public vm::Host {
 public:
  Firmware(dialect::Runtime& runtime, dialect::WireStyle wire_style);

  // --- dialect::Firmware ---
  const dialect::WireForm& wire() const override { return wire_; }
  void boot(std::vector<std::string>& messages) override;
  // How often the drive has booted: a host's PLCDL transfer begun before a reboot is gone.
  uint64_t boot_count() const { return boots_; }
  uint64_t cycle_ns() const override { return kStepNs; }
  void cycle(const std::vector<uint32_t>& drive_events) override;
  std::unique_ptr<dialect::Session> open_session() override;
  std::vector<dialect::Answer> query(std::string_view line) override { return command_line(line); }
  dialect::DownloadResult download(const std::vector<uint8_t>& source) override;
  std::string start(std::string_view entry) override;
  bool running() const override { return plc_state() == 1; }
  int32_t program_error() const override { return static_cast<int32_t>(run_error_); }
  std::string program_error_text() const override;
  std::string state_summary() const override;
  std::vector<dialect::ThreadInfo> threads() const override;
  // The debugger (docs/debugging.md): the PLC programs are its threads; an expression in ST.
  const dialect::LoadedProgram* loaded_program() const override { return program_.get(); }
  dialect::LoadedProgram* debug_program() override { return program_.get(); }
  void debug_runs(uint32_t thread) override { debugger_runs_ = thread; }
  // {"source": PATH}: the name of the file the source just stored came from (debug_hooks.cpp).
  void set_debug_map(std::string_view map) override;
  // The name the stored source compiles under: its file's, when the controller said it.
  std::string source_name() const;
  dialect::Evaluation evaluate(uint32_t thread, uint32_t depth,
                               std::string_view expression) override;  // debug_hooks.cpp

  // --- vm::Host ---
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override;
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override;
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t count) override;
  vm::CommandStatus message(uint32_t thread, uint32_t text, const Value* args,
                            uint32_t count) override;
  uint32_t now_us() override { return static_cast<uint32_t>(runtime_.now_ns() / 1000); }

  // One host line: its answers (command_line.cpp); a session also lets one axis step pass.
  std::vector<dialect::Answer> command_line(std::string_view line);
  void spend_line_time() { runtime_.advance_ns(kStepNs); }
  // The output stage is on: the page lets the program be modified only while it is not.
  bool stage_on() const;

 private:
  friend class CommandLine;
  // --- the PLC (firmware.cpp) ---
  int32_t plc_state() const;    // PLC: 1 running, 0 stopped, -1 failed, -2 no source
  int32_t compile_and_start();  // 0, or the ASCII error (11 compile failed)
  void report_compile(const CompileResult& r);
  void stop_plc(uint32_t failed = scheduling::kNoThread);  // a failed program stays where it failed
  void latch(int fault);
  void record_axis_faults();  // command_line.cpp
  void on_report(const scheduling::Report& report);
  void sync_user_variables_out();
  std::optional<int32_t> parameter_value(std::string_view name);
  void say(const std::string& line) { runtime_.output(line + "\n"); }

  // --- the debug commands (debug_commands.cpp) ---
  std::vector<dialect::Answer> debug_command(const std::string& name,
                                             const std::vector<std::string>& words);
  std::string program_state(uint32_t thread) const;

  // --- parameters (settings.cpp) ---
  void defaults();
  std::string saved_text() const;
  void apply_saved(const std::string& text);
  int32_t save();
  int32_t load();

  // --- motion (motion.cpp) ---
  struct Deferred {
    enum Kind : uint8_t { kNone, kJog, kTask } kind = kNone;
    int32_t a = 0, b = 0;  // J's rpm and ms; MOVE's task
  };
  double counts_exact(double user) const;
  int32_t counts_of(int64_t user) const;
  int32_t user_of(double counts) const;
  void apply_limits();
  bool defer_until_ready(Deferred::Kind kind, int32_t a, int32_t b);
  int32_t start_homing();
  // MH's searching types (homing.cpp): 1 and 3 to the reference switch, 2 and 4 to a limit
  // switch, 7 and 9 to a mechanical stop; 1, 2 and 7 go on to a zero mark.
  struct SwitchHoming {
    enum Phase : uint8_t { kIdle, kLeave, kSearch, kBack, kMark, kStop, kReturn } phase = kIdle;
    enum Criterion : uint8_t { kReferenceSwitch, kLimitSwitch, kMechanicalStop };
    Criterion criterion = kReferenceSwitch;
    int input = 0;             // 1..4 (the switch types)
    bool zero_mark = false;    // NREF 1, 2, 7: the first zero mark after the criterion
    bool mark_behind = false;  // NREF 2, 7: that mark lies back, away from the limit or stop
    double direction = -1.0;   // DREF 0 negative, 1 positive
    double capture = 0.0;      // the reference point (motor counts) once found
    double last_motor = 0.0;   // the motor's position a cycle ago, for the zero mark
  };
  int32_t start_switch_homing(int32_t nref);
  // --- the analog inputs (analog.cpp) ---
  bool world_directive(std::string_view name, std::string_view arg, std::string& failure) override;
  int32_t analog_input_mv(int n) const;  // ANIN1/ANIN2: the level, within ±10 V
  void step_analog_speed();              // OPMODE 1: SW1 × VSCALE1 as the speed command
  void step_switch_homing();
  void head_for(double motor_counts);  // a move at the homing speed to a motor position
  bool homing_input_active() const;
  bool homing_criterion_met() const;
  void found_criterion(double motor_counts);
  void end_homing();
  void set_reference();
  void set_reference(double at_motor);
  int32_t feedback_within_turn() const;
  int32_t within_turn(double motor_counts) const;
  int32_t start_task(int32_t nr);
  void step_motion();
  int32_t jog(int32_t rpm, int32_t ms);
  // STOP: a motion task decelerates with its own d, a jog, homing or analog speed with DECSTOP.
  void stop_motion();
  // The axis decelerates to a stop at `decel` counts/s² (its own stop ramp, Gold's SD, stays).
  void stop_axis_with(double decel);
  double rpm_to_counts(double rpm) const;
  double ramp_counts_per_s2(int32_t ms) const;

  dialect::Runtime& runtime_;
  bool in_program_ = false;  // inside a host call of the program: nothing may replace it
  int32_t prompt_ = 0;
  int32_t msg_ = 0;
  S300Wire wire_;
  drive::Axis* axis_ = nullptr;

  // Parameters the firmware keeps (the saved ones among them go to the settings record).
  std::map<std::string, int32_t> values_;
  std::array<int32_t, kUserVariables> user_vars_{};

  // The stored source, and the compiled program in RAM.
  std::optional<std::string> source_;
  // The file name set_debug_map() gave and the source it was given for: a source stored later
  // without a name (PLCDL lines) compiles as program.st again.
  std::string source_name_;
  std::string named_source_;
  std::unique_ptr<dialect::LoadedProgram> program_;
  std::vector<bytecode::Global> globals_;  // the loaded program's, for the command line
  std::vector<uint8_t> global_bits_;       // their widths (CompileResult::global_bits)
  scheduling::CyclicTasks schedule_;
  uint32_t debugger_runs_ = scheduling::kNoThread;  // debug_runs()
  std::string running_here() const;
  std::vector<std::pair<uint32_t, std::string>> threads_;  // thread, program name
  bool compile_failed_ = false;
  uint64_t boots_ = 0;
  bool plc_started_ = false;
  vm::RunError run_error_ = vm::RunError::None;
  std::set<int> faults_;  // F31, F32 (the firmware's); the axis' come from its MF

  // Motion.
  std::map<int32_t, MotionTask> tasks_;
  int32_t mtmux_ = 0;
  int32_t last_move_ = 0;
  int32_t opmode_ = 8;
  bool enabled_ = false;
  double target_counts_ = 0;  // the last task's target, exact (between counts in user units)
  bool homing_ = false;       // MH's move to a zero mark is under way
  double homing_mark_ = 0;    // that mark, in motor counts
  SwitchHoming switch_homing_;
  bool reference_set_ = false;  // STATUS word 5 bit 1: a homing (MH, SETREF) set the point
  double refpos_motor_ = 0;     // REFPOS: where the last homing saw its criterion (motor counts)
  std::array<int32_t, 4> input_modes_{};  // IN1MODE…IN4MODE as the last boot took them
  int32_t ancnfg_ = 0;                    // ANCNFG as the last boot took it
  std::array<int32_t, 2> analog_mv_{};    // SW1, SW2: the world's levels (a reboot keeps them)
  std::optional<double> analog_rpm_;      // the speed OPMODE 1 last commanded
  Deferred deferred_;                     // a J or MOVE waiting for the end of EN's enable delay
  bool next_pending_ = false;
  int32_t next_task_ = 0;
  uint64_t next_at_ns_ = 0;
  uint64_t jog_until_ns_ = 0;
};

}  // namespace uprog::st
