// The studio's live scope: the drive's recorder re-armed before every step of time, so that every
// servo cycle's sample of the chosen channels (signals and program globals) reaches the page, none
// dropped. Trigger, pre-trigger and decimation are the page's: it holds the stream.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "controller/controller.h"

namespace uprog::studio {

// Samples of every channel from `first_time_us` on, one every `period_us`, sample-major.
struct ScopeBlock {
  uint64_t first_time_us = 0;
  uint32_t period_us = 0;
  uint32_t channels = 0;
  std::vector<double> values;  // samples x channels
  size_t samples() const { return channels == 0 ? 0 : values.size() / channels; }
};

class ScopeStream {
 public:
  static constexpr size_t kMaxChannels = 8;

  explicit ScopeStream(controller::Controller& drive) : drive_(drive) {}

  // The channels by name ("PX", "VX", a global "cnt" or "arr[2]"); "" or why not (nothing
  // changes then). An empty list stops the scope and leaves the recorder alone.
  std::string choose(const std::vector<std::string>& names);
  const std::vector<drive::Channel>& channels() const { return channels_; }
  // Before `ns` of virtual time passes: the recorder armed with room for every cycle of it.
  // "" or why the recorder refused.
  std::string prepare(uint64_t ns);
  // After it: what was recorded since prepare(); nullopt when nothing was.
  std::optional<ScopeBlock> collect();

 private:
  controller::Controller& drive_;
  std::vector<drive::Channel> channels_;
};

// A block as the page reads it: float64 little-endian words [first_time_us, period_us, channels,
// samples, then the values sample-major].
std::string encode_block(const ScopeBlock& block);

}  // namespace uprog::studio
