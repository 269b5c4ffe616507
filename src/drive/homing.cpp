// The homing process's event detection and the index pulse's crossing test.
#include "drive/homing.h"

#include <cmath>

namespace uprog::drive {

std::optional<double> Homing::step(HomeTrigger trigger, const HomingCycle& cycle) {
  if (!armed_) return std::nullopt;
  std::optional<double> at;
  switch (trigger) {
    case HomeTrigger::kImmediate:
      at = cycle.position_counts;
      break;
    case HomeTrigger::kHomeInput:
      if (cycle.switch_edge) at = cycle.position_counts;
      break;
    case HomeTrigger::kIndex:
      at = cycle.index_at_counts;
      break;
    case HomeTrigger::kHomeInputThenIndex:
      // An index met in the same cycle as the edge lies before it: not yet.
      if (home_input_seen_) at = cycle.index_at_counts;
      if (cycle.switch_edge) home_input_seen_ = true;
      break;
  }
  if (at) armed_ = false;
  return at;
}

std::optional<double> index_crossed(double offset_counts, double period_counts, double from_counts,
                                    double to_counts) {
  if (!(period_counts > 0.0) || from_counts == to_counts) return std::nullopt;
  // Pulse k lies at offset + k * period; count the pulses in (from, to] or [to, from).
  const double k_from = (from_counts - offset_counts) / period_counts;
  const double k_to = (to_counts - offset_counts) / period_counts;
  // The first pulse after `from` in the direction of travel.
  const double k = to_counts > from_counts ? std::floor(k_from) + 1.0 : std::ceil(k_from) - 1.0;
  if (to_counts > from_counts ? k > k_to : k < k_to) return std::nullopt;
  return offset_counts + k * period_counts;
}

}  // namespace uprog::drive
