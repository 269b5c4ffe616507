// The AG300 controller's firmware (dialect::Firmware): the CUP program in flash and its image in
// RAM, threads 1..8 on rate priorities (one CUP line per due thread per cycle), the A-prefixed
// command line (thread 0's stacks for CUP keywords sent over the line), and the VM's Host.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dialect/firmware.h"
#include "dialect/loaded_program.h"
#include "dialect/runtime.h"
#include "dialect/scheduling/rate_priorities.h"
#include "dialects/pup/cup_file.h"
#include "dialects/pup/cup_loader.h"
#include "dialects/pup/debug_map.h"
#include "dialects/pup/download.h"
#include "dialects/pup/message.h"
#include "dialects/pup/pup_wire.h"

namespace uprog::pup {

constexpr uint32_t kThreads = 8;

// One host's download in progress (ADownloadUProg[1..3]); it dies with the connection. A fault
// drops the transfer: 40 until the next [1].
struct DownloadState {
  dialect::DownloadReceiver transfer{kMaxProgramBytes, kCupDownloadCodes, kMaxChunkBytes};
};

class Firmware final : public dialect::Firmware, public vm::Host {
 public:
  Firmware(dialect::Runtime& runtime, const dialect::FirmwareOptions& options);

  const dialect::WireForm& wire() const override { return wire_; }
  void boot(std::vector<std::string>& messages) override;
  uint64_t cycle_ns() const override { return 50'000; }
  void cycle(const std::vector<uint32_t>& drive_events) override;
  std::unique_ptr<dialect::Session> open_session() override;
  std::vector<dialect::Answer> query(std::string_view line) override { return send(line, false); }
  dialect::DownloadResult download(const std::vector<uint8_t>& bytes) override;
  std::string start(std::string_view entry) override;
  bool running() const override;
  int32_t program_error() const override;
  std::string program_error_text() const override;
  std::string state_summary() const override;
  std::vector<dialect::ThreadInfo> threads() const override;

  // --- debug_hooks.cpp: the debugger's hooks (dialect/firmware.h) ---
  const dialect::LoadedProgram* loaded_program() const override { return program_.get(); }
  dialect::LoadedProgram* debug_program() override { return program_.get(); }
  std::optional<drive::ProgramWords::Word> recorder_word(std::string_view name) const override;
  dialect::Evaluation evaluate(uint32_t thread, uint32_t depth,
                               std::string_view expression) override;
  void set_debug_map(std::string_view map) override;
  std::vector<dialect::DebugVariable> debug_variables() override;

  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override;
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override;
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t count) override;
  uint32_t now_us() override { return static_cast<uint32_t>(runtime_.now_ns() / 1000); }

  // One host line: its messages (split at `;`), each answered, each a cycle when `takes_time`.
  std::vector<dialect::Answer> send(std::string_view line, bool takes_time,
                                    DownloadState* download = nullptr);

 private:
  // --- firmware.cpp: program store, threads ---
  std::string install(const std::string& cup, bool store);
  int32_t run_task(uint32_t thread, int32_t task);
  int32_t program_status(uint32_t thread) const;
  void on_thread_error(uint32_t thread);
  void log_error(int32_t code, int32_t source, int32_t line);
  vm::Machine* machine() { return program_ ? &program_->machine() : nullptr; }
  uint32_t running_thread() const;
  std::string place_of(uint32_t cup_line) const;
  void debug_runs(uint32_t thread) override { debugger_runs_ = thread; }
  uint32_t next_line(uint32_t thread) const;

  // --- events.cpp: latching, masks, entering thread 1 and leaving ---
  void latch_events(uint32_t drive_events);
  void latch(int32_t id);
  void take_event();          // cycle() calls it with an event latched
  void check_event_return();  // ... and this one inside an event routine
  void reset_events();

  // --- program_control.cpp: single steps, breakpoints, the call stack ---
  int32_t single_step(uint32_t thread, int32_t kind);
  int32_t set_breaks(uint32_t thread, int32_t value);
  int32_t clear_stacks(uint32_t thread, bool expression_stack);
  std::string breaks_list(uint32_t thread) const;
  std::string call_stack(uint32_t thread) const;
  int32_t set_pointer(uint32_t thread, int32_t line);
  int32_t expression_stack(uint32_t thread, std::string& list) const;
  // cycle() calls it when a thread had an event or one is stepping.
  void after_cycle(const scheduling::Report& report);
  // A line of ProgBreaks in any thread's list: a trap elsewhere is the debugger's to handle.
  bool break_line_in_use(uint32_t line) const;
  // The debug map's PUP places as the image's line table, when the map is this program's.
  void apply_debug_map(const std::string& cup, bytecode::Image& image) const;

  // --- keywords.cpp side (controller_keywords.cpp): parameters and commands ---
  int32_t read_key(KeywordId key, int32_t index, int32_t& out);
  int32_t write_key(KeywordId key, int32_t index, int32_t value);
  int32_t run_key(KeywordId key, int32_t index, bool has_arg, int32_t arg, uint32_t thread);
  int32_t status_of(int32_t s, int32_t v);
  int32_t set_motion_mode(int32_t mode);
  int32_t set_input_function(int32_t n, int32_t function);

 public:
  // --- the world a transcript changes (docs/transcripts.md: analog, comm-error) ---
  bool world_directive(std::string_view name, std::string_view arg, std::string& failure) override;
  // A line the framer refused (too long, a bad byte): event 23, the communication error, and the
  // host's error in AErrLog (code, source 0, line 0).
  void on_framing_error(int32_t code) {
    latch(23);
    log_error(code, 0, 0);
  }

 private:
  // --- command_line.cpp ---
  dialect::Answer serve_message(std::string_view text, DownloadState* download);
  dialect::Answer download_message(int32_t step, const std::optional<std::string>& argument,
                                   DownloadState& d);
  dialect::Answer upload(int32_t offset);
  std::vector<dialect::Answer> info();
  dialect::Answer line_stack(const Message& m, const Keyword& k);

  dialect::Runtime& runtime_;
  PupWire wire_;
  scheduling::RatePriorities schedule_;
  uint32_t debugger_runs_ = scheduling::kNoThread;  // debug_runs()
  drive::Axis* axis_ = nullptr;

  std::optional<std::string> stored_;
  bool flash_read_ = false;
  std::unique_ptr<dialect::LoadedProgram> program_;
  LoadedCup cup_;
  CupProgram cup_program_;
  std::optional<DebugMap> debug_map_;
  std::string debug_map_cup_;  // the CUP text the map belongs to

  std::array<Value, kGenDataSize> gen_data_{};
  std::array<int32_t, 4> timers_{};
  uint32_t timer_us_ = 0;
  std::array<int32_t, kThreads + 1> thread_error_{};
  std::vector<int32_t> line_stack_;              // thread 0: the CUP keywords sent over the line
  std::vector<std::array<int32_t, 3>> err_log_;  // newest first: code, source, line
  struct Single {
    bool over = false;  // Type != 0: until the pointer leaves the line at the same call depth
    uint32_t line = 0, depth = 0;
  };
  std::array<Single, kThreads + 1> single_{};
  uint32_t stepping_ = 0;  // the threads an AProgSingle runs, bit t for thread t
  std::array<std::vector<uint32_t>, kThreads + 1> breaks_{};  // lines, ascending
  uint32_t event_mask_ = 0x00FFFFFF;
  uint32_t latched_ = 0;  // event IDs latched, one bit each
  struct EventEntry {
    uint32_t frames;       // thread 1's frame count inside the event
    uint32_t held_before;  // the threads 2..8 held when it entered (a bit each): held again after
  };
  std::vector<EventEntry> event_frames_;  // each event entered, innermost last
  uint32_t previous_inputs_ = 0;          // input levels, bit n-1 for input n
  bool was_moving_ = false;
  bool above_max_ = false, below_min_ = false;
  int32_t motion_mode_ = 0;
  int32_t speed_ = 10000;
  int32_t ain_factor_ = 1, ain_offset_ = 0;
  int32_t analog_mv_ = 0;                // the analog input (the transcript's `analog = MV`)
  std::array<int32_t, 6> in_func_{};     // AInFunc[1..6]: 0 general purpose
  int32_t curr_cmd_ = 0;                 // ACurrCmd, mA
  int32_t abs_trgt_ = 0, rel_trgt_ = 0;  // what the next ABegin moves to, or by
};

}  // namespace uprog::pup
