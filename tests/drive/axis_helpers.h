// Shared set-up for the axis tests: run the axis for a span of virtual time.
#pragma once
#include <cstdint>

#include "drive/axis.h"

namespace uprog::drive::testing {

// Steps until `us` microseconds of virtual time have passed; returns the OR of the events.
inline uint32_t run_us(Axis& axis, uint64_t us) {
  uint32_t events = 0;
  for (uint64_t t = 0; t < us; t += axis.period_us()) events |= axis.step();
  return events;
}

// MO=1 and wait past the enable delay.
inline void enable(Axis& axis) {
  axis.set_motor_on(true);
  run_us(axis, kEnableDelay_us + 5000);
}

inline void set_motion(Axis& axis, int32_t sp, int32_t ac, int32_t dc) {
  axis.parameters().speed_counts_per_s = sp;
  axis.parameters().accel_counts_per_s2 = ac;
  axis.parameters().decel_counts_per_s2 = dc;
}

}  // namespace uprog::drive::testing
