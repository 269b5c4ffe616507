// Gold's recorder commands (recorder_commands.h). What each follows, quoted in
// docs/dialects/gold.md
// ("The recorder"): RC "a bit field. Each on bit ... defines a signal to be recorded" (MAN-SIMCR
// 3-122), RG "Range: [1…4096]" and "Recorder inactive" (3-123), RR's options 0..3 and reports
// -1, 0, 1..3 (3-128), RP[0..7] (Software Manual tables 7-4 and the one before it, 7.4.5), RP[8],
// RP[9] the upload range (7.4.7), SR bits 16-17 (table 7-5).
#include "dialects/gold/recorder_commands.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>

#include "dialects/gold/drive_commands.h"
#include "dialects/gold/recorder_signals.h"

namespace uprog::gold {
namespace {

constexpr int32_t kErrorNoSuchVariable =
    209;  // as interpreter_errors.h's: DB##RV[n]'s name is gone
constexpr int32_t kErrorOk = 0;

bool rp_in_range(int32_t index, int32_t v) {
  switch (index) {
    case 0:
      return v == 0 || v == 1;  // 4 TS or TS
    case 1:
      return v == 0 ||
             (v > 0 && v < (1 << kRecorderSlots) && std::has_single_bit(static_cast<uint32_t>(v)));
    case 2:
      return v >= 0 && v <= 100;  // percent
    case 3:
      return v >= 0 && v <= 6;  // 0..5 the reference's, 6 uprog's window entry
    case 6:
    case 7:
      return v >= 0 && v < (1 << drive::kInputCount);
    case 8:
    case 9:
      return v >= 0;
    default:
      return true;  // RP[4], RP[5]: levels
  }
}

// BH's record (MAN-SIMSW 7.4.7's table; table 8-8 of the Harmonica manual): each field as
// hexadecimal digits, most significant nibble first.
void append_hex(std::string& out, uint32_t value, int digits) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%0*x", digits, value);
  out.append(buf, static_cast<size_t>(digits));
}

// A float signal goes up as whole micro-units with the factor 1e-6 ("provides the scaling
// multiplier to relate it to user units"); an integer signal as it is, with the factor 1.
constexpr double kFloatUploadUnit = 1e-6;
constexpr uint16_t kMaxUploadItems = 0xFFFF;  // the record's data length is one word

uint32_t upload_item(double value, bool is_float) {
  if (!is_float) return static_cast<uint32_t>(static_cast<int32_t>(value));
  const double units =
      std::clamp(std::round(value / kFloatUploadUnit), -2147483648.0, 2147483647.0);
  return static_cast<uint32_t>(static_cast<int32_t>(units));
}

bool settings_command(uint16_t id, int32_t index) {
  return id == RC || id == RV || id == RL || id == RG || (id == RP && index < 8);
}

}  // namespace

uint32_t RecorderCommands::report() const {
  switch (axis_.recorder().state()) {
    case drive::RecorderState::kIdle:
      return static_cast<uint32_t>(-1);
    case drive::RecorderState::kDone:
      return 0;
    default:
      return static_cast<uint32_t>(launched_);
  }
}

int32_t RecorderCommands::read(uint16_t id, int32_t index, Value& out) const {
  int32_t v = 0;
  switch (id) {
    case RV:
      v = signals_[static_cast<size_t>(index - 1)];
      break;
    case RC:
      v = rc_;
      break;
    case RL:
      v = length_;
      break;
    case RG:
      v = gap_;
      break;
    case RP:
      v = rp_[static_cast<size_t>(index)];
      break;
    case RR:
      v = static_cast<int32_t>(report());
      break;
    case WI:
      v = samples_recorded();
      break;
    default:
      return kErrorOutOfRange;
  }
  out = Value::of_int(v);
  return kErrorOk;
}

int32_t RecorderCommands::write(uint16_t id, int32_t index, Value value) {
  const int32_t v = value.i;
  drive::Recorder& recorder = axis_.recorder();
  if (id == RR) return launch(v);
  if (settings_command(id, index)) {
    // "Restrictions: Recorder inactive (RR=0 or RR=-1)"; "setting RC will invalidate this data".
    if (recorder.active()) return kErrorRecorderBusy;
    if (id == RC || id == RG) recorder.invalidate();
  }
  switch (id) {
    case RV: {
      const size_t slot = static_cast<size_t>(index - 1);
      if (v != 0 && recorder_signal_by_id(v) == nullptr &&
          !(v == kRecorderVariableSignal && !variables_[slot].empty()))
        return kErrorOutOfRange;
      if (v != kRecorderVariableSignal) variables_[slot].clear();
      signals_[slot] = v;
      return kErrorOk;
    }
    case RC:
      rc_ = v;
      return kErrorOk;
    case RL:
      length_ = v;
      return kErrorOk;
    case RG:
      gap_ = v;
      return kErrorOk;
    case RP:
      if (!rp_in_range(index, v)) return kErrorOutOfRange;
      rp_[static_cast<size_t>(index)] = v;
      return kErrorOk;
    default:
      return kErrorOutOfRange;
  }
}

void RecorderCommands::map_variable(int32_t n, std::string name) {
  const size_t slot = static_cast<size_t>(n - 1);
  variables_[slot] = std::move(name);
  signals_[slot] = kRecorderVariableSignal;
}

uint32_t RecorderCommands::status_bits() const {
  constexpr uint32_t kBit16 = 1u << 16, kBit17 = 1u << 17;
  switch (axis_.recorder().state()) {
    case drive::RecorderState::kIdle:
      return 0;
    case drive::RecorderState::kArmed:
    case drive::RecorderState::kWaiting:
      return kBit17;  // armed, waiting for the trigger
    case drive::RecorderState::kTriggered:
      return kBit16 | kBit17;  // recording now
    case drive::RecorderState::kDone:
      return kBit16;  // valid data ready
  }
  return 0;
}

int32_t RecorderCommands::samples_recorded() const {
  return static_cast<int32_t>(axis_.recorder().samples_recorded());
}

int32_t RecorderCommands::upload(int32_t n, std::string& out) const {
  const drive::Recorder& recorder = axis_.recorder();
  // "To execute a BH command, valid data must be stored in the recorder."
  if (recorder.state() != drive::RecorderState::kDone) return kErrorRecorderNoData;
  // "BH=16 will return an error because BH&RC=0"; with several bits "the variable with the
  // lowest value will be uploaded". RC cannot have changed since: setting it invalidates.
  const uint32_t bits = static_cast<uint32_t>(rc_) & static_cast<uint32_t>(n);
  if (bits == 0) return kErrorOutOfRange;
  const uint32_t bit = bits & (~bits + 1);
  const auto channel = static_cast<size_t>(std::popcount(static_cast<uint32_t>(rc_) & (bit - 1)));
  const std::optional<drive::Recording> recording = recorder.recording(axis_.period_us());
  const drive::RecordedChannel& signal = recording->channels[channel];
  // RP[8]..RP[9]: the first index and one past the last ("RP[9] must always equal or be less
  // than the length of the recorded signal"); both 0: the whole signal.
  size_t first = 0, end = signal.values.size();
  if (rp_[8] != 0 || rp_[9] != 0) {
    first = static_cast<size_t>(rp_[8]);
    end = static_cast<size_t>(rp_[9]);
    if (first >= end || end > signal.values.size()) return kErrorOutOfRange;
  }
  if (end - first > kMaxUploadItems) return kErrorOutOfRange;
  const bool variable =
      signals_[static_cast<size_t>(std::countr_zero(bit))] == kRecorderVariableSignal;
  const uint32_t type = (variable ? 2u : 0u) + (signal.is_float ? 1u : 0u);
  const float factor = signal.is_float ? static_cast<float>(kFloatUploadUnit) : 1.0f;
  out.clear();
  out.reserve(20 + (end - first) * 8);
  append_hex(out, type, 2);
  append_hex(out, 8, 2);  // data width: long integers
  append_hex(out, static_cast<uint32_t>(end - first), 4);
  append_hex(out, recorder.settings().gap_cycles, 4);  // the sample period in TS
  append_hex(out, std::bit_cast<uint32_t>(factor), 8);
  for (size_t i = first; i < end; ++i)
    append_hex(out, upload_item(signal.values[i], signal.is_float), 8);
  return kErrorOk;
}

int32_t RecorderCommands::channel_of(size_t slot, drive::Channel& out) const {
  const int32_t id = signals_[slot];
  if (id == kRecorderVariableSignal) {
    const drive::ProgramWords* words = axis_.recorder().program_words();
    std::optional<drive::Channel> c;
    if (words != nullptr) c = drive::global_channel(*words, variables_[slot], nullptr);
    if (!c) return kErrorNoSuchVariable;
    out = std::move(*c);
    return kErrorOk;
  }
  const RecorderSignal* s = recorder_signal_by_id(id);
  if (s == nullptr) return kErrorRecorderNoSignals;
  out = drive::signal_channel(s->signal, std::string(s->name));
  return kErrorOk;
}

// RR=-1 kills and invalidates, 0 kills (a complete recording stays), 1..3 launch: 1 and 2 are 3
// with RP[3] = 1 (BG) and 0 (immediate), as the Software Manual's 7.4.6 says.
int32_t RecorderCommands::launch(int32_t mode) {
  drive::Recorder& recorder = axis_.recorder();
  if (mode == -1) {
    recorder.invalidate();
    return kErrorOk;
  }
  if (mode == 0) {
    recorder.kill();
    return kErrorOk;
  }
  drive::RecorderSettings s;
  for (size_t slot = 0; slot < kRecorderSlots; ++slot) {
    if ((rc_ & (1 << slot)) == 0) continue;
    drive::Channel c;
    if (const int32_t e = channel_of(slot, c)) return e;
    s.channels.push_back(std::move(c));
  }
  if (s.channels.empty()) return kErrorRecorderNoSignals;
  const int32_t type = mode == 1 ? 1 : mode == 2 ? 0 : rp_[3];
  using drive::TriggerKind;
  constexpr TriggerKind kByType[] = {TriggerKind::kImmediate,   TriggerKind::kBeginMotion,
                                     TriggerKind::kRising,      TriggerKind::kFalling,
                                     TriggerKind::kWindowLeave, TriggerKind::kInput,
                                     TriggerKind::kWindowEnter};
  s.trigger.kind = kByType[type];
  if (type >= 2 && type != 5) {
    // RP[1]: "Similar to RC, but only 1 bit may be non-zero"; the signal need not be recorded.
    if (rp_[1] == 0) return kErrorRecorderNoSignals;
    if (const int32_t e = channel_of(
            static_cast<size_t>(std::countr_zero(static_cast<uint32_t>(rp_[1]))), s.trigger.source))
      return e;
  }
  // RP[4]: "Level of positive slope trigger, or high side of window"; RP[5] the negative slope's,
  // the low side.
  s.trigger.level = type == 3 ? rp_[5] : rp_[4];
  s.trigger.low = rp_[5];
  s.trigger.input_polarity = static_cast<uint32_t>(rp_[6]);
  s.trigger.input_mask = static_cast<uint32_t>(rp_[7]);
  s.pretrigger_percent = static_cast<uint32_t>(rp_[2]);
  s.gap_cycles =
      static_cast<uint32_t>(gap_) * (rp_[0] == 0 ? 4u : 1u);  // RP[0]=0: the 4 TS quantum
  // "If RL > (recorder memory) / (number of signals), the recorder ... will record up to its data
  // volume."
  s.length = static_cast<uint32_t>(
      std::min<size_t>(static_cast<size_t>(length_), drive::kMaxRecorderWords / s.channels.size()));
  std::string why;
  if (!recorder.arm(s, &why)) return kErrorOutOfRange;
  launched_ = mode;
  return kErrorOk;
}

}  // namespace uprog::gold
