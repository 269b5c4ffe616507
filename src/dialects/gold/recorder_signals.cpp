// The table of Gold's recorder signals (recorder_signals.h). The numbers are this simulated
// drive's own: the Elmo reference lets each drive list its recordable signals (LS, LP) and
// RV[n] maps one of them to RC's bit n-1; ours follow the order of drive::Signal.
#include "dialects/gold/recorder_signals.h"

#include <array>

namespace uprog::gold {
namespace {

using drive::Signal;

constexpr std::array kTable{
    RecorderSignal{1, "PX", Signal::kPosition},
    RecorderSignal{2, "VX", Signal::kVelocity},
    RecorderSignal{3, "PE", Signal::kPositionError},
    RecorderSignal{4, "DV[3]", Signal::kReferencePosition},
    RecorderSignal{5, "DV[2]", Signal::kReferenceVelocity},
    RecorderSignal{6, "DV[1]", Signal::kCurrentCommand},
    RecorderSignal{7, "IQ", Signal::kActiveCurrent},
    RecorderSignal{8, "IP", Signal::kInputPort},
    RecorderSignal{9, "OP", Signal::kOutputPort},
    RecorderSignal{10, "MS", Signal::kMotionStatus},
    RecorderSignal{11, "PY", Signal::kAuxPosition},
};

bool same_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const auto up = [](char c) {
      return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
    };
    if (up(a[i]) != up(b[i])) return false;
  }
  return true;
}

}  // namespace

std::optional<drive::Signal> recorder_signal(std::string_view name) {
  for (const RecorderSignal& s : kTable)
    if (same_ignoring_case(s.name, name)) return s.signal;
  return std::nullopt;
}

const RecorderSignal* recorder_signal_by_id(int32_t id) {
  for (const RecorderSignal& s : kTable)
    if (s.id == id) return &s;
  return nullptr;
}

const RecorderSignal* recorder_signal_of(drive::Signal signal) {
  for (const RecorderSignal& s : kTable)
    if (s.signal == signal) return &s;
  return nullptr;
}

}  // namespace uprog::gold
