// The debugger, dialect-neutral: over a simulated drive's controller, the firmware's debug hooks
// (dialect/firmware.h) and the VM's breakpoints. Line and function breakpoints with conditions,
// hit counts and log messages; break on run-time errors; pause; step in, over and out by source
// line; continue. All-stop: when the program stops, every thread of it stops and virtual time
// stands still, since time passes only in run(), one firmware cycle at a time.
#pragma once
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "debug/hit_condition.h"

namespace uprog::debug {

struct BreakpointSpec {
  uint32_t line = 0;          // a source line; for a function breakpoint unused
  std::string function;       // a routine's name; for a line breakpoint empty
  std::string condition;      // an expression in the program's dialect; empty: always
  std::string hit_condition;  // hit_condition.h
  std::string log_message;    // non-empty: log this ({expr} replaced) instead of stopping
};

struct BreakpointState {
  uint32_t id = 0;
  bool verified = false;
  std::string file;     // the line table's name of the file, when verified
  uint32_t line = 0;    // where it stands (a line without code moves to the next one with code)
  std::string message;  // why it is not verified
};

enum class StepKind : uint8_t { In, Over, Out };
enum class StopReason : uint8_t { Entry, Breakpoint, FunctionBreakpoint, Step, Pause, Exception };
// The Debug Adapter Protocol's name of a reason ("breakpoint", "function breakpoint", ...).
const char* stop_reason_name(StopReason reason);

struct Stop {
  StopReason reason = StopReason::Pause;
  uint32_t thread = 0;
  std::string description;            // the run-time error, for an exception
  std::vector<uint32_t> breakpoints;  // the ids of the breakpoints hit
};

enum class RunState : uint8_t { Running, Stopped, Ended };

struct StackFrame {
  uint32_t depth = 0;  // 0 is the innermost
  std::string routine;
  std::string file;  // "" without a line table
  uint32_t line = 0;
  uint32_t pc = 0;
  bool is_event = false;  // an event routine entered on top of the thread
};

struct Variable {
  std::string name;
  std::string value;
  std::string type;       // "int", "float", or a signal's unit
  uint32_t elements = 0;  // an array's length (its elements are elements()), 0 for a scalar
};

// What set_variable() gives: the value now stored, or why nothing was stored.
struct SetResult {
  bool ok = false;
  std::string value;
  std::string error;
};

class Debugger {
 public:
  explicit Debugger(controller::Controller& drive);

  // --- breakpoints: each call replaces that file's (or all function) breakpoints ---
  std::vector<BreakpointState> set_line_breakpoints(const std::string& file,
                                                    const std::vector<BreakpointSpec>& specs);
  std::vector<BreakpointState> set_function_breakpoints(const std::vector<BreakpointSpec>& specs);
  void set_break_on_error(bool on) { break_on_error_ = on; }
  void clear_breakpoints();

  // --- execution ---
  // The program has been started: stop before its first line runs.
  void stop_at_entry();
  // Continue every thread.
  void resume();
  // Step `thread` by a source line; the other threads run too unless `single_thread`.
  void step(uint32_t thread, StepKind kind, bool single_thread = false);
  // Stop now, where every thread stands.
  void pause();
  // While stopped: true when a thread runs again, resumed by other means than this debugger (a
  // line typed at the drive's command line: Gold's XC, DB##GO); the debugger then runs on too.
  bool resumed_elsewhere();
  // Lets the drive run, cycle by cycle, until the program stops or ends or `budget_ns` of
  // virtual time has passed.
  RunState run(uint64_t budget_ns);
  RunState state() const { return state_; }
  const Stop& last_stop() const { return stop_; }
  // The log messages of breakpoints that log instead of stopping, since the last call.
  std::vector<std::string> take_messages();

  // --- inspection (inspect.cpp), meaningful while stopped ---
  std::vector<dialect::ThreadInfo> threads() const;
  std::vector<StackFrame> stack(uint32_t thread) const;
  std::vector<Variable> locals(uint32_t thread, uint32_t depth) const;
  std::vector<Variable> globals() const;
  std::vector<Variable> elements(uint32_t global) const;
  // The drive's signals: position, velocity, status words (read only).
  std::vector<Variable> signals() const;
  int find_global(const std::string& name) const;
  SetResult set_local(uint32_t thread, uint32_t depth, const std::string& name,
                      const std::string& text);
  SetResult set_global(uint32_t global, uint32_t element, const std::string& text);
  // In the program's dialect (the firmware's evaluate()); a dialect without one gets a variable
  // looked up by name.
  dialect::Evaluation evaluate(uint32_t thread, uint32_t depth, const std::string& expression);

  controller::Controller& drive() { return drive_; }
  // The firmware may have loaded another program (a launch, a line typed at the command line):
  // the breakpoints find their places in it before it runs on.
  void program_changed() { armed_for_ = nullptr; }

 private:
  struct Armed {
    uint32_t id;
    std::string file;  // the file asked for; empty for a function breakpoint
    BreakpointSpec spec;
    HitCondition hit;
    uint64_t hits = 0;
    std::optional<uint32_t> pc;  // where it is set in the current program
    BreakpointState state;
    bool malformed = false;  // its hit condition cannot be read: never set
  };
  struct Stepping {
    uint32_t thread;
    StepKind kind;
    uint32_t depth;
    uint32_t pc;
  };

  dialect::LoadedProgram* program() const;
  void resolve(Armed& b) const;
  Armed make_breakpoint(std::string file, const BreakpointSpec& spec);
  // Sets the machine's traps to the breakpoints and step traps, after the program changed too.
  void arm();
  void after_cycle();
  // A thread stands at a trap: true when it stops the program.
  bool at_trap(uint32_t thread);
  bool step_done(uint32_t thread) const;
  uint32_t call_depth(uint32_t thread) const;
  // Runs the stepping thread up to its next line end or wait, then one cycle: the time that passed.
  uint64_t step_slice();
  uint64_t advance_one_cycle();
  // A line that never ends (a hand-made image's loop) still lets time pass.
  static constexpr uint32_t kStepInstructionsPerCycle = 100'000;
  std::string interpolate(uint32_t thread, const std::string& message);
  void stop(StopReason reason, uint32_t thread, std::string description = {},
            std::vector<uint32_t> ids = {});
  void start_running(std::optional<uint32_t> only_thread);
  std::vector<BreakpointState> states_of(bool functions) const;

  controller::Controller& drive_;
  std::vector<Armed> breakpoints_;
  uint32_t next_id_ = 1;
  bool break_on_error_ = false;
  std::optional<Stepping> stepping_;
  RunState state_ = RunState::Running;
  Stop stop_;
  std::vector<uint32_t> halted_;  // threads the debugger halted, to resume
  // The thread a stop showed, where it stood, when it goes on: a breakpoint set on that very
  // place while it stood there is no hit as it leaves (as in gdb), only when it comes back.
  struct Standing {
    uint32_t thread;
    uint32_t pc;
  };
  std::optional<Standing> standing_;
  std::vector<uint8_t> seen_error_;  // per thread: its error has been reported
  dialect::LoadedProgram* armed_for_ = nullptr;
  std::set<uint32_t> armed_pcs_;
  std::vector<std::string> messages_;
};

}  // namespace uprog::debug
