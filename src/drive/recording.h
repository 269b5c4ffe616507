// A finished recording: channels of samples at one sampling period around a trigger, as the
// recorder hands it out, the CSV file holds it and `uprog plot` and `--expect` read it back.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace uprog::drive {

struct RecordedChannel {
  std::string name;  // as the user named it: "PX", "position", "cnt", "arr[2]"
  std::string unit;  // "counts", "counts/s", "A"; "" for a program variable
  bool is_float = false;
  std::vector<double> values;  // exact: int32 or float32 values
  bool operator==(const RecordedChannel&) const = default;
};

struct Recording {
  uint32_t sample_period_us = 0;  // the servo period times the gap
  std::string trigger;  // how it was triggered: "immediate", "begin", "rising PX 1000", ...
  uint32_t pretrigger_percent = 0;
  uint32_t trigger_index = 0;    // the sample taken at (or first after) the trigger
  uint64_t trigger_time_us = 0;  // the drive's time of that sample
  std::vector<RecordedChannel> channels;
  size_t samples() const { return channels.empty() ? 0 : channels.front().values.size(); }
  // Time of sample i relative to the trigger, in microseconds (negative before it).
  int64_t time_us(size_t i) const {
    return (static_cast<int64_t>(i) - static_cast<int64_t>(trigger_index)) * sample_period_us;
  }
  bool operator==(const Recording&) const = default;
};

// How far a channel may differ from its reference (`--tolerance CH=V`); exact otherwise.
struct Tolerance {
  std::string channel;
  double value = 0.0;
};

// The first sample and channel where `actual` differs from `expected` beyond the tolerances, or
// a difference of shape (channels, period, samples); nullopt when they agree.
struct Difference {
  std::string text;  // "PX at 12.500 ms (sample 130): 10412, expected 10400 (tolerance 0)"
};
std::optional<Difference> compare(const Recording& actual, const Recording& expected,
                                  const std::vector<Tolerance>& tolerances);

}  // namespace uprog::drive
