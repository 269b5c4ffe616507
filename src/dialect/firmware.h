// A dialect's side of a drive: what the controller calls. It loads the stored form of a program
// into a verified image, answers host lines, runs its threads and events once per cycle in its
// own schedule, and tells the host and the debugger what each thread is doing.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/answer.h"
#include "dialect/loaded_program.h"
#include "dialect/scheduling/whole_lines.h"
#include "dialect/wire_form.h"
#include "drive/recorder.h"
#include "vm/machine.h"

namespace uprog::dialect {

// How much of the program runs in each cycle, where a dialect lets the user choose (Gold: source
// lines per background slice; `uprog run --budget`). A dialect with a fixed schedule ignores it.
using Timing = scheduling::LineTiming;

struct FirmwareOptions {
  Timing timing;
  bool safe_boot = false;  // boot without starting the program (Gold: no AUTOEXEC)
  WireStyle wire_style = WireStyle::kDrive;
};

// The result of giving the drive a program's stored form.
struct DownloadResult {
  bool ok = false;
  std::string error;            // why it was refused; the stored program is then unchanged
  bool storage_failed = false;  // it was sound, but the flash could not take it
};

// One thread of the program, for the host and the debugger.
struct ThreadInfo {
  uint32_t thread = 0;
  std::string name;  // "program", "task 2", "PLC62"
  vm::ThreadStatus status = vm::ThreadStatus::Idle;
  std::string where;  // "file.ehl:12", or "" when idle
  int32_t error = 0;  // the last run-time error (vm RunError), 0 for none
};

// What an expression evaluated for the debugger gave: its value in the dialect's own words, and
// whether it counts as true (a breakpoint's condition), or why it could not be evaluated.
struct Evaluation {
  bool ok = false;
  std::string value;  // the value as the dialect shows it ("7", "2.5"), several joined by ", "
  bool is_true = false;
  std::string error;  // why not, when !ok
};

// A variable the dialect keeps outside the image's globals (PUP's #definevar names for
// AGenData), for the debugger's Globals.
struct DebugVariable {
  std::string name;
  std::string value;  // as the dialect shows it; an array's elements joined by ", " in brackets
  std::string type;
};

// A frame of a thread that the dialect builds itself rather than the VM (PDL's procedures, whose
// frames are words in the task's stack), for the debugger's call stack.
struct DebugFrame {
  std::string routine;
  uint32_t pc = 0;  // the code word whose line it stands at: the innermost's own, a caller's call
  std::vector<DebugVariable> locals;  // its parameters, then its locals
};

// One host's conversation with the drive: what belongs to that host alone (a download in
// progress, a host level) lives here and dies with the connection.
class Session {
 public:
  virtual ~Session() = default;
  // One host line as the wire framed it (a transcript's `>` line may hold several expressions);
  // the answers in order. It takes the virtual time the drive's line handling takes.
  virtual std::vector<Answer> send(std::string_view line) = 0;
};

class Firmware {
 public:
  virtual ~Firmware() = default;

  virtual const WireForm& wire() const = 0;
  // Power-up and reset, after the controller has made fresh axes: read the stored program,
  // load it and start what starts at power-up. Problems go to `messages`.
  virtual void boot(std::vector<std::string>& messages) = 0;
  // How often cycle() runs; the controller steps the axes on their own periods in between.
  virtual uint64_t cycle_ns() const = 0;
  // One cycle of the program's schedule. `drive_events` are the axes' event bits
  // (drive/events.h) since the last cycle, one word per axis.
  virtual void cycle(const std::vector<uint32_t>& drive_events) = 0;

  virtual std::unique_ptr<Session> open_session() = 0;
  // As a session's send(), but taking no virtual time: for recorders and tools sampling the drive.
  virtual std::vector<Answer> query(std::string_view line) = 0;

  // Stores a program's stored form (checked first); it runs once loaded.
  virtual DownloadResult download(const std::vector<uint8_t>& stored_form) = 0;
  // Loads the stored program and starts it as `uprog run` does: at `entry`, or where the
  // dialect starts a program when `entry` is empty. "" on success, else why not.
  virtual std::string start(std::string_view entry) = 0;
  // True while any thread of the program runs or waits.
  virtual bool running() const = 0;
  // The program's last run-time error (vm RunError), 0 for none, and its text.
  virtual int32_t program_error() const = 0;
  virtual std::string program_error_text() const = 0;
  // The drive's state in the dialect's own words, for the last line of `uprog run`.
  virtual std::string state_summary() const = 0;
  virtual std::vector<ThreadInfo> threads() const = 0;

  // A transcript directive for the world outside the axis that only this dialect's drive has
  // (PUP's `analog = MV`, `comm-error`; docs/transcripts.md): false when it is not one of its
  // directives; a directive it refuses says why in `failure`.
  virtual bool world_directive(std::string_view name, std::string_view arg, std::string& failure) {
    (void)name, (void)arg, (void)failure;
    return false;
  }

  // --- for the recorder (drive/recorder.h); defaults for a dialect that has not said ---
  // The program in RAM, whose globals the recorder's channels may read; null for none.
  virtual const LoadedProgram* loaded_program() const { return nullptr; }
  // The dialect's own name of an axis signal ("PX" for Gold); nullopt: not one of its names.
  virtual std::optional<drive::Signal> recorder_signal(std::string_view name) const {
    (void)name;
    return std::nullopt;
  }
  // A program word by the dialect's own name, counted as its manual counts (the AG300's
  // "AGenData[3]", a #definevar name); nullopt: the neutral lookup, a global as name[element].
  virtual std::optional<drive::ProgramWords::Word> recorder_word(std::string_view name) const {
    (void)name;
    return std::nullopt;
  }

  // --- for the debugger (src/debug); the defaults offer nothing, so a dialect adds them as it can
  // --- The program in RAM (its machine and hosted image: line table, locals), or nullptr.
  virtual LoadedProgram* debug_program() { return nullptr; }
  // An expression in the dialect's syntax, seeing the locals of frame `depth` (0 innermost) of
  // `thread` and the globals; what it assigns stays assigned. It takes no virtual time.
  virtual Evaluation evaluate(uint32_t /*thread*/, uint32_t /*depth*/,
                              std::string_view /*expression*/) {
    return {false, {}, false, "this dialect evaluates no expressions for the debugger"};
  }
  // The debug map (dialect::CompileOutput::debug_map) of the program just downloaded, given by the
  // controller when it compiled the program itself: the line table and names it lends the
  // debugger while that program is stored. The default ignores it.
  virtual void set_debug_map(std::string_view /*map*/) {}
  // Variables beyond the image's globals, by the dialect's names; the default has none.
  virtual std::vector<DebugVariable> debug_variables() { return {}; }
  // The frames of `thread`, innermost first, where the dialect keeps them itself; nullopt (the
  // default) when the VM's frames are the program's.
  virtual std::optional<std::vector<DebugFrame>> debug_frames(uint32_t /*thread*/) {
    return std::nullopt;
  }
  // The number of frames debug_frames() would give, for stepping over and out: asked at each line
  // start while a step runs, so cheaper than the frames. nullopt: the VM's frame count.
  virtual std::optional<uint32_t> debug_call_depth(uint32_t /*thread*/) { return std::nullopt; }
  // A step runs its thread outside the firmware's schedule (the debugger's own slices): while it
  // does, `thread` names it, so that the host calls made meanwhile know whose they are (PUP's
  // return check, PDL's lock); scheduling::kNoThread when the step's slice is over.
  virtual void debug_runs(uint32_t /*thread*/) {}
  // The code word where a function breakpoint on `name` stands, for a routine of the dialect's
  // that is no image routine (a PDL procedure); nullopt (the default): none.
  virtual std::optional<uint32_t> debug_function_entry(std::string_view /*name*/) {
    return std::nullopt;
  }
  // Sets a local of a frame of debug_frames(): the value now stored, or why not (.ok false).
  virtual Evaluation set_debug_local(uint32_t /*thread*/, uint32_t /*depth*/,
                                     std::string_view /*name*/, std::string_view /*value*/) {
    return {false, {}, false, "this dialect has no frames of its own"};
  }
  // As start(), with inputs for the entry routine (the debugger's `args`): "" or why not.
  virtual std::string start_with_arguments(std::string_view entry,
                                           const std::vector<double>& args) {
    return args.empty() ? start(entry) : "this dialect starts a program without arguments";
  }
};

}  // namespace uprog::dialect
