// The recorder's states, trigger and sampling (recorder.h). The pre-trigger share is a ring in the
// first part of the memory; the trigger sample and those after it follow it in order.
#include "drive/recorder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <utility>

#include "drive/axis.h"
#include "drive/inputs.h"

namespace uprog::drive {
namespace {

constexpr std::array kSignals{
    SignalInfo{Signal::kPosition, "position", "counts", false},
    SignalInfo{Signal::kVelocity, "velocity", "counts/s", false},
    SignalInfo{Signal::kPositionError, "position_error", "counts", false},
    SignalInfo{Signal::kReferencePosition, "reference_position", "counts", false},
    SignalInfo{Signal::kReferenceVelocity, "reference_velocity", "counts/s", false},
    SignalInfo{Signal::kCurrentCommand, "current_command", "A", true},
    SignalInfo{Signal::kActiveCurrent, "active_current", "A", true},
    SignalInfo{Signal::kInputPort, "input_port", "", false},
    SignalInfo{Signal::kOutputPort, "output_port", "", false},
    SignalInfo{Signal::kMotionStatus, "motion_status", "", false},
    SignalInfo{Signal::kAuxPosition, "aux_position", "counts", false},
};
static_assert(kSignals.size() == kSignalCount, "one row per Signal, in its order");

uint32_t int_bits(int32_t v) { return static_cast<uint32_t>(v); }
uint32_t float_bits(float v) { return std::bit_cast<uint32_t>(v); }

double value_of(uint32_t bits, bool is_float) {
  return is_float ? static_cast<double>(std::bit_cast<float>(bits))
                  : static_cast<double>(static_cast<int32_t>(bits));
}

std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

std::span<const SignalInfo> all_signals() { return kSignals; }
const SignalInfo& signal_info(Signal signal) { return kSignals[static_cast<size_t>(signal)]; }

const SignalInfo* find_signal(std::string_view name) {
  for (const SignalInfo& s : kSignals)
    if (s.name == name) return &s;
  return nullptr;
}

Channel signal_channel(Signal signal, std::string name) {
  const SignalInfo& info = signal_info(signal);
  Channel c;
  c.name = std::move(name);
  c.unit = std::string(info.unit);
  c.signal = signal;
  c.is_float = info.is_float;
  return c;
}

std::optional<ElementName> split_element_name(std::string_view text) {
  const size_t open = text.find('[');
  if (open == std::string_view::npos) return ElementName{text, std::nullopt};
  const std::string_view digits = text.substr(open + 1, text.size() - open - 2);
  uint32_t index = 0;
  const auto [p, e] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (text.back() != ']' || digits.empty() || e != std::errc() ||
      p != digits.data() + digits.size()) {
    return std::nullopt;
  }
  return ElementName{text.substr(0, open), index};
}

std::optional<Channel> global_channel(const ProgramWords& words, std::string_view text,
                                      std::string* why) {
  const std::optional<ElementName> element = split_element_name(text);
  if (!element) {
    if (why) *why = "'" + std::string(text) + "': expected name[index] with a number";
    return std::nullopt;
  }
  const std::optional<ProgramWords::Word> word =
      words.find_global(element->name, element->index.value_or(0));
  if (!word) {
    if (why) *why = "'" + std::string(text) + "' is no signal and no global of the program";
    return std::nullopt;
  }
  return word_channel(*word, std::string(text));
}

Channel word_channel(const ProgramWords::Word& word, std::string name) {
  Channel c;
  c.name = std::move(name);
  c.is_global = true;
  c.address = word.address;
  c.is_float = word.is_float;
  c.bound = word.bound;
  return c;
}

std::string Trigger::describe() const {
  switch (kind) {
    case TriggerKind::kImmediate:
      return "immediate";
    case TriggerKind::kBeginMotion:
      return "begin";
    case TriggerKind::kRising:
      return "rising " + source.name + " " + number_text(level);
    case TriggerKind::kFalling:
      return "falling " + source.name + " " + number_text(level);
    case TriggerKind::kWindowLeave:
      return "leave " + source.name + " " + number_text(low) + " " + number_text(level);
    case TriggerKind::kWindowEnter:
      return "enter " + source.name + " " + number_text(low) + " " + number_text(level);
    case TriggerKind::kInput:
      return "input mask " + std::to_string(input_mask) + " polarity " +
             std::to_string(input_polarity);
  }
  return "?";
}

bool Recorder::arm(const RecorderSettings& settings, std::string* why) {
  auto refuse = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (settings.channels.empty()) return refuse("the recorder needs at least one channel");
  if (settings.channels.size() > kMaxRecorderChannels)
    return refuse("the recorder takes at most 16 channels");
  if (settings.length < 1) return refuse("the recording length is at least one sample");
  if (settings.gap_cycles < 1) return refuse("the gap is at least one servo cycle");
  if (settings.pretrigger_percent > 100) return refuse("the pre-trigger share is 0..100 percent");
  if (size_t{settings.length} * settings.channels.size() > kMaxRecorderWords)
    return refuse("the recording does not fit the recorder's memory (4194304 words)");
  settings_ = settings;
  memory_.assign(size_t{settings.length} * settings.channels.size(), 0);
  plan_sampling();
  pre_ = static_cast<uint32_t>(uint64_t{settings.length} * settings.pretrigger_percent / 100);
  if (pre_ >= settings.length) pre_ = settings.length - 1;  // the trigger sample needs its slot
  pre_taken_ = 0;
  ring_slot_ = 0;
  post_taken_ = 0;
  phase_ = 0;  // the first cycle after arming takes a sample
  begun_ = false;
  fired_ = false;
  has_previous_ = false;
  previous_condition_ = false;
  trigger_time_us_ = 0;
  state_ = pre_ == 0 ? RecorderState::kWaiting : RecorderState::kArmed;
  return true;
}

// Which channel each signal is sampled into, which channels read the program, which repeat a
// signal another channel has: worked out once here, so that a sample is only reads and stores.
void Recorder::plan_sampling() {
  row_words_ = static_cast<uint32_t>(settings_.channels.size());
  global_channels_.clear();
  bound_channels_.clear();
  repeated_channels_.clear();
  needed_signals_ = 0;
  for (size_t c = 0; c < settings_.channels.size(); ++c) {
    const Channel& channel = settings_.channels[c];
    const auto here = static_cast<uint8_t>(c);
    if (channel.bound != nullptr) {
      bound_channels_.emplace_back(here, channel.bound);
      continue;
    }
    if (channel.is_global) {
      global_channels_.emplace_back(here, channel.address);
      continue;
    }
    const auto signal = static_cast<unsigned>(channel.signal);
    if (needed_signals_ & (1u << signal)) {
      repeated_channels_.emplace_back(here, channel_of_signal_[signal]);
    } else {
      needed_signals_ |= 1u << signal;
      channel_of_signal_[signal] = here;
    }
  }
}

void Recorder::kill() {
  if (active()) invalidate();
}

void Recorder::invalidate() {
  state_ = RecorderState::kIdle;
  memory_.clear();
  memory_.shrink_to_fit();
}

uint32_t Recorder::samples_recorded() const {
  switch (state_) {
    case RecorderState::kIdle:
      return 0;
    case RecorderState::kArmed:
    case RecorderState::kWaiting:
      return static_cast<uint32_t>(std::min<uint64_t>(pre_taken_, pre_));
    case RecorderState::kTriggered:
    case RecorderState::kDone:
      return static_cast<uint32_t>(std::min<uint64_t>(pre_taken_, pre_)) + post_taken_;
  }
  return 0;
}

namespace {

template <Signal S>
uint32_t signal_bits(const Axis& axis) {
  if constexpr (S == Signal::kPosition) return int_bits(axis.position());
  if constexpr (S == Signal::kVelocity) return int_bits(axis.velocity());
  if constexpr (S == Signal::kPositionError) return int_bits(axis.position_error());
  if constexpr (S == Signal::kReferencePosition) return int_bits(axis.reference_position());
  if constexpr (S == Signal::kReferenceVelocity) return int_bits(axis.reference_velocity());
  if constexpr (S == Signal::kCurrentCommand) return float_bits(axis.current_command());
  if constexpr (S == Signal::kActiveCurrent)
    return float_bits(static_cast<float>(axis.motor_state().current_a));
  if constexpr (S == Signal::kInputPort) return axis.input_port();
  if constexpr (S == Signal::kOutputPort) return axis.output_port();
  if constexpr (S == Signal::kMotionStatus) return int_bits(axis.motion_status());
  if constexpr (S == Signal::kAuxPosition) return int_bits(axis.aux_position());
}

using SignalReader = uint32_t (*)(const Axis&);
template <size_t... I>
constexpr std::array<SignalReader, sizeof...(I)> signal_readers(std::index_sequence<I...>) {
  return {&signal_bits<static_cast<Signal>(I)>...};
}
constexpr auto kSignalReaders = signal_readers(std::make_index_sequence<kSignalCount>{});

// Each signal in `needed` (bit n: Signal n) into its channel row[channel[n]], read inline: one
// test and one read per signal, no dispatch and no copy (the servo cycle's cost with 8
// channels, bench/micro).
template <size_t... I>
void write_signals(uint32_t needed, const Axis& axis, const uint8_t* channel, uint32_t* row,
                   std::index_sequence<I...>) {
  ((needed & (1u << I) ? void(row[channel[I]] = signal_bits<static_cast<Signal>(I)>(axis))
                       : void()),
   ...);
}

}  // namespace

uint32_t Recorder::read_bits(const Channel& c, const Axis& axis) const {
  if (c.bound != nullptr) return static_cast<uint32_t>(c.bound->i);
  if (c.is_global) return word_bits(program_memory(), c.address);
  return kSignalReaders[static_cast<size_t>(c.signal)](axis);
}

std::span<const Value> Recorder::program_memory() const {
  return words_ != nullptr ? words_->memory() : std::span<const Value>{};
}

uint32_t Recorder::word_bits(std::span<const Value> memory, uint32_t address) {
  return address < memory.size() ? static_cast<uint32_t>(memory[address].i) : 0u;
}

double Recorder::read_value(const Channel& c, const Axis& axis) const {
  return value_of(read_bits(c, axis), c.is_float);
}

// Every cycle, armed or waiting: edges are judged against the previous cycle's value, so an edge
// that happens while the pre-trigger share is still being recorded is missed (manual 7.4.5).
bool Recorder::trigger_fired(const Axis& axis) {
  const Trigger& t = settings_.trigger;
  bool fired = false;
  switch (t.kind) {
    case TriggerKind::kImmediate:
      fired = true;
      break;
    case TriggerKind::kBeginMotion:
      fired = begun_;
      break;
    case TriggerKind::kRising:
    case TriggerKind::kFalling: {
      const double v = read_value(t.source, axis);
      if (has_previous_) {
        fired = t.kind == TriggerKind::kRising ? previous_ < t.level && v >= t.level
                                               : previous_ > t.level && v <= t.level;
      }
      previous_ = v;
      has_previous_ = true;
      break;
    }
    case TriggerKind::kWindowLeave:
    case TriggerKind::kWindowEnter:
    case TriggerKind::kInput: {
      bool condition = false;
      if (t.kind == TriggerKind::kInput) {
        uint32_t active = 0;
        for (int n = 1; n <= kInputCount; ++n)
          if (axis.input_active(n)) active |= 1u << (n - 1);
        condition = (active & t.input_mask) == (t.input_polarity & t.input_mask);
      } else {
        const double v = read_value(t.source, axis);
        const bool inside = v >= t.low && v <= t.level;
        condition = t.kind == TriggerKind::kWindowEnter ? inside : !inside;
      }
      fired = has_previous_ && condition && !previous_condition_;
      previous_condition_ = condition;
      has_previous_ = true;
      break;
    }
  }
  begun_ = false;
  return fired && (state_ == RecorderState::kWaiting ||
                   (state_ == RecorderState::kArmed && settings_.early_trigger));
}

void Recorder::write_row(uint32_t* out, const Axis& axis) const {
  write_signals(needed_signals_, axis, channel_of_signal_.data(), out,
                std::make_index_sequence<kSignalCount>{});
  if (!global_channels_.empty()) {
    const std::span<const Value> memory = program_memory();
    for (const auto& [c, address] : global_channels_) out[c] = word_bits(memory, address);
  }
  for (const auto& [c, word] : bound_channels_) out[c] = static_cast<uint32_t>(word->i);
  for (const auto& [to, from] : repeated_channels_) out[to] = out[from];
}

// After the trigger the rows follow the ring in order; before it, the ring's slot wraps without
// a division (the servo cycle's cost, bench/micro).
void Recorder::take_sample(const Axis& axis) {
  if (state_ == RecorderState::kTriggered) return take_sample_after_trigger(axis);
  write_row(memory_.data() + size_t{ring_slot_} * row_words_, axis);
  if (++ring_slot_ == pre_) ring_slot_ = 0;
  if (++pre_taken_ == pre_) state_ = RecorderState::kWaiting;
}

// Armed or waiting: the trigger is judged every cycle, and the cycle it fires in may be the
// trigger sample's.
void Recorder::on_cycle_before_trigger(const Axis& axis) {
  if (!fired_ && trigger_fired(axis)) {
    fired_ = true;
    if (pre_ == 0) phase_ = 0;  // no earlier samples to keep in step with: the trigger cycle is one
  }
  if (phase_ != 0) {
    --phase_;
    return;
  }
  phase_ = settings_.gap_cycles - 1;
  if (fired_ && (state_ == RecorderState::kWaiting || state_ == RecorderState::kArmed)) {
    if (state_ == RecorderState::kArmed)
      pre_ = static_cast<uint32_t>(pre_taken_);  // in order from slot 0
    post_length_ = settings_.length - pre_;
    state_ = RecorderState::kTriggered;
    trigger_time_us_ = axis.time_us();
  }
  if (state_ == RecorderState::kWaiting && pre_ == 0) return;  // nothing before the trigger to keep
  take_sample(axis);
}

std::optional<Recording> Recorder::recording(uint32_t servo_period_us) const {
  if (state_ != RecorderState::kTriggered && state_ != RecorderState::kDone) return std::nullopt;
  Recording r;
  r.sample_period_us = servo_period_us * settings_.gap_cycles;
  r.trigger = settings_.trigger.describe();
  r.pretrigger_percent = settings_.pretrigger_percent;
  const uint32_t before = static_cast<uint32_t>(std::min<uint64_t>(pre_taken_, pre_));
  r.trigger_index = before;
  r.trigger_time_us = trigger_time_us_;
  const size_t n = settings_.channels.size();
  r.channels.resize(n);
  for (size_t c = 0; c < n; ++c) {
    const Channel& ch = settings_.channels[c];
    RecordedChannel& out = r.channels[c];
    out.name = ch.name;
    out.unit = ch.unit;
    out.is_float = ch.is_float;
    out.values.reserve(before + post_taken_);
    // The ring's oldest sample first: it sits where the next one would have gone.
    for (uint32_t i = 0; i < before; ++i) {
      const size_t slot = static_cast<size_t>((pre_taken_ - before + i) % pre_);
      out.values.push_back(value_of(memory_[slot * n + c], ch.is_float));
    }
    for (uint32_t i = 0; i < post_taken_; ++i)
      out.values.push_back(value_of(memory_[(pre_ + i) * n + c], ch.is_float));
  }
  return r;
}

}  // namespace uprog::drive
