// Gold's names of the recorder's axis signals (PX, VX, PE, DV[n], IQ, IP, OP, MS, PY) and the
// signal numbers RV[n] takes for them (docs/dialects/gold.md, "The recorder").
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "drive/recorder.h"

namespace uprog::gold {

struct RecorderSignal {
  int32_t id;             // RV[n]'s value
  std::string_view name;  // the command that reads it: "PX", "DV[3]"
  drive::Signal signal;
};

// RV[n] of a program variable mapped with DB##RV[n]=var.
constexpr int32_t kRecorderVariableSignal = 1023;

std::optional<drive::Signal> recorder_signal(std::string_view name);  // case-insensitive
const RecorderSignal* recorder_signal_by_id(int32_t id);
const RecorderSignal* recorder_signal_of(drive::Signal signal);

}  // namespace uprog::gold
