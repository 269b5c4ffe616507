// Comparing a recording with a reference (recording.h): what `uprog run --expect` and the
// transcripts' `expect` lines report.
#include "drive/recording.h"

#include <fmt/core.h>

#include <cmath>

namespace uprog::drive {
namespace {

double tolerance_of(const std::vector<Tolerance>& tolerances, const std::string& channel) {
  for (const Tolerance& t : tolerances)
    if (t.channel == channel) return t.value;
  return 0.0;
}

std::string value_text(double v) { return fmt::format("{}", v); }

}  // namespace

std::optional<Difference> compare(const Recording& actual, const Recording& expected,
                                  const std::vector<Tolerance>& tolerances) {
  auto differ = [](std::string text) {
    return std::optional<Difference>(Difference{std::move(text)});
  };
  for (const Tolerance& t : tolerances) {
    bool known = false;
    for (const RecordedChannel& c : expected.channels) known = known || c.name == t.channel;
    if (!known)
      return differ(
          fmt::format("--tolerance {}: the reference has no channel '{}'", t.channel, t.channel));
  }
  if (actual.channels.size() != expected.channels.size())
    return differ(
        fmt::format("{} channels, expected {}", actual.channels.size(), expected.channels.size()));
  for (size_t c = 0; c < actual.channels.size(); ++c) {
    if (actual.channels[c].name != expected.channels[c].name)
      return differ(fmt::format("channel {} is '{}', expected '{}'", c + 1, actual.channels[c].name,
                                expected.channels[c].name));
  }
  if (actual.sample_period_us != expected.sample_period_us)
    return differ(fmt::format("sampling period {} us, expected {} us", actual.sample_period_us,
                              expected.sample_period_us));
  if (actual.trigger_index != expected.trigger_index)
    return differ(fmt::format("the trigger is sample {}, expected sample {}", actual.trigger_index,
                              expected.trigger_index));
  // Sample by sample, the channels in order: the first difference in time is the one named.
  const size_t n = std::min(actual.samples(), expected.samples());
  for (size_t i = 0; i < n; ++i) {
    for (size_t c = 0; c < actual.channels.size(); ++c) {
      const double a = actual.channels[c].values[i], e = expected.channels[c].values[i];
      const double tol = tolerance_of(tolerances, expected.channels[c].name);
      if (std::fabs(a - e) <= tol) continue;
      return differ(fmt::format("{} at {:.3f} ms (sample {}): {}, expected {} (tolerance {})",
                                expected.channels[c].name,
                                static_cast<double>(expected.time_us(i)) / 1000.0, i, value_text(a),
                                value_text(e), value_text(tol)));
    }
  }
  if (actual.samples() != expected.samples())
    return differ(fmt::format("{} samples, expected {} (they agree up to {:.3f} ms)",
                              actual.samples(), expected.samples(),
                              static_cast<double>(expected.time_us(n)) / 1000.0));
  return std::nullopt;
}

}  // namespace uprog::drive
