// The drive's recorder: axis signals and program words sampled every N servo cycles into memory
// taken when it is armed, around a trigger with a pre-trigger share (docs/recorder.md). The axis
// calls on_cycle() after each step while the recorder is active; nothing there allocates.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "drive/recording.h"
#include "support/value.h"

namespace uprog::drive {

class Axis;

// The axis signals a channel can record, named neutrally; a dialect maps its own names onto them.
enum class Signal : uint8_t {
  kPosition,           // PX, counts
  kVelocity,           // VX, counts/s
  kPositionError,      // PE, counts
  kReferencePosition,  // DV[3], counts
  kReferenceVelocity,  // DV[2], counts/s
  kCurrentCommand,     // DV[1], A
  kActiveCurrent,      // IQ, A
  kInputPort,          // IP
  kOutputPort,         // OP
  kMotionStatus,       // MS
  kAuxPosition,        // PY, counts
};
constexpr size_t kSignalCount = static_cast<size_t>(Signal::kAuxPosition) + 1;

struct SignalInfo {
  Signal signal;
  std::string_view name;  // "position"
  std::string_view unit;  // "counts"
  bool is_float;
};
std::span<const SignalInfo> all_signals();
const SignalInfo& signal_info(Signal signal);
const SignalInfo* find_signal(std::string_view name);

// The program's data memory as the recorder reads it; the controller lends it the program in RAM.
class ProgramWords {
 public:
  struct Word {
    uint32_t address = 0;  // in the data memory (architecture.md, "The data memory")
    bool is_float = false;
    // A global the firmware keeps outside the data memory (Machine::bind_global: PUP's AGenData),
    // read where it lives; such words outlive every program, so the pointer stays valid.
    const Value* bound = nullptr;
  };
  // A global's element by name; nullopt when the program has no such global or element.
  virtual std::optional<Word> find_global(std::string_view name, uint32_t element) const = 0;
  // The data memory's words (architecture.md, "The data memory"); empty without a program.
  // Asked once per sample, so that a program's channels cost a load each.
  virtual std::span<const Value> memory() const = 0;

 protected:
  ~ProgramWords() = default;
};

struct Channel {
  std::string name;  // as the user named it
  std::string unit;
  bool is_global = false;
  Signal signal = Signal::kPosition;
  uint32_t address = 0;  // a global's word
  bool is_float = false;
  const Value* bound = nullptr;  // a global's word the firmware keeps (ProgramWords::Word)
};

Channel signal_channel(Signal signal, std::string name);
// "name" or "name[i]" split into the name and the index (none without brackets); nullopt when
// the brackets do not hold a number alone.
struct ElementName {
  std::string_view name;
  std::optional<uint32_t> index;
};
std::optional<ElementName> split_element_name(std::string_view text);
// A channel of one program word, named as the user named it.
Channel word_channel(const ProgramWords::Word& word, std::string name);
// "name" or "name[i]" as a program global; nullopt with `why` when there is none.
std::optional<Channel> global_channel(const ProgramWords& words, std::string_view text,
                                      std::string* why);

enum class TriggerKind : uint8_t {
  kImmediate,    // as soon as the pre-trigger share is recorded
  kBeginMotion,  // a BG (a command, a program, a begin input)
  kRising,       // the source crosses `level` upwards
  kFalling,      // the source crosses `level` downwards
  kWindowLeave,  // the source leaves [low, high]
  kWindowEnter,  // the source enters [low, high]
  kInput,        // the inputs in `input_mask` reach the logical states of `input_polarity`
};

struct Trigger {
  TriggerKind kind = TriggerKind::kImmediate;
  Channel source;                // the level and window triggers' signal; it need not be recorded
  double level = 0.0;            // rising, falling; the window's high side
  double low = 0.0;              // the window's low side
  uint32_t input_mask = 0;       // bit n-1 for input n
  uint32_t input_polarity = 0;   // the logical state each masked input must reach
  std::string describe() const;  // "rising PX 1000", the recording's header
};

struct RecorderSettings {
  std::vector<Channel> channels;
  uint32_t gap_cycles = 1;  // a sample every gap servo cycles
  uint32_t length = 1024;   // samples per channel
  uint32_t pretrigger_percent = 0;
  Trigger trigger;
  // A trigger before the pre-trigger share is full is taken with the samples there are (the
  // share shrinks, the length stays); without it, it is missed, as Elmo's recorder misses it.
  bool early_trigger = false;
};

constexpr size_t kMaxRecorderChannels = 16;
constexpr size_t kMaxRecorderWords = size_t{1} << 22;  // samples times channels: 16 MB

enum class RecorderState : uint8_t {
  kIdle,       // no valid data
  kArmed,      // recording the pre-trigger share; a trigger now is missed
  kWaiting,    // the pre-trigger share is full: waiting for the trigger
  kTriggered,  // recording after the trigger
  kDone,       // the recording is complete
};

class Recorder {
 public:
  // Takes the memory and starts recording; false with `why` for unusable settings.
  bool arm(const RecorderSettings& settings, std::string* why);
  // Stops; data recorded so far is dropped unless the recording was complete.
  void kill();
  // Drops everything: kIdle.
  void invalidate();
  RecorderState state() const { return state_; }
  bool active() const {
    return state_ == RecorderState::kArmed || state_ == RecorderState::kWaiting ||
           state_ == RecorderState::kTriggered;
  }
  const RecorderSettings& settings() const { return settings_; }
  // Samples per channel recorded so far (the pre-trigger ring counts what it holds).
  uint32_t samples_recorded() const;

  // The program words global channels read; null: they read 0.
  void set_program_words(const ProgramWords* words) { words_ = words; }
  const ProgramWords* program_words() const { return words_; }
  // A BG was performed; the next cycle sees it.
  void on_begin() { begun_ = true; }
  // After each servo step while active(): evaluate the trigger, take a sample every gap cycles.
  // Inline: after the trigger there is nothing to judge, and a cycle is a sample or a count.
  void on_cycle(const Axis& axis) {
    if (state_ != RecorderState::kTriggered) return on_cycle_before_trigger(axis);
    if (phase_ != 0) {
      --phase_;
      return;
    }
    phase_ = settings_.gap_cycles - 1;
    take_sample_after_trigger(axis);
  }

  // What was recorded, in time order, once triggered (partly, while still recording); nullopt
  // before the trigger.
  std::optional<Recording> recording(uint32_t servo_period_us) const;

 private:
  uint32_t read_bits(const Channel& channel, const Axis& axis) const;
  std::span<const Value> program_memory() const;
  static uint32_t word_bits(std::span<const Value> memory, uint32_t address);  // 0 outside it
  double read_value(const Channel& channel, const Axis& axis) const;
  bool trigger_fired(const Axis& axis);
  void plan_sampling();
  void on_cycle_before_trigger(const Axis& axis);
  void take_sample(const Axis& axis);
  void take_sample_after_trigger(const Axis& axis) {  // the rows follow the ring in order
    write_row(memory_.data() + size_t{pre_ + post_taken_} * row_words_, axis);
    if (++post_taken_ == post_length_) state_ = RecorderState::kDone;
  }
  void write_row(uint32_t* out, const Axis& axis) const;  // one sample of every channel

  RecorderSettings settings_;
  RecorderState state_ = RecorderState::kIdle;
  const ProgramWords* words_ = nullptr;
  std::vector<uint32_t> memory_;  // length x channels words, sample-major
  // The sampling plan (plan_sampling): the signals read, the channel each goes into, the
  // channels of program words (channel, address), and channels that repeat an earlier one's
  // signal (to, from).
  uint32_t row_words_ = 0;       // a sample of every channel
  uint32_t needed_signals_ = 0;  // bit n: Signal n
  std::array<uint8_t, kSignalCount> channel_of_signal_{};
  std::vector<std::pair<uint8_t, uint32_t>> global_channels_;
  std::vector<std::pair<uint8_t, const Value*>> bound_channels_;
  std::vector<std::pair<uint8_t, uint8_t>> repeated_channels_;
  uint32_t pre_ = 0;          // samples before the trigger sample
  uint64_t pre_taken_ = 0;    // samples written into the pre-trigger ring
  uint32_t ring_slot_ = 0;    // pre_taken_ % pre_: where the ring's next sample goes
  uint32_t post_length_ = 0;  // length - pre_: the samples from the trigger sample on
  uint32_t post_taken_ = 0;   // samples from the trigger sample on
  uint32_t phase_ = 0;        // cycles until the next sample
  bool begun_ = false;
  bool fired_ = false;  // the trigger fired; the next sample is the trigger sample
  bool has_previous_ = false;
  double previous_ = 0.0;
  bool previous_condition_ = false;
  uint64_t trigger_time_us_ = 0;
};

}  // namespace uprog::drive
