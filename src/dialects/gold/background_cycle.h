// How long one pass of the Gold drive's background loop takes (manual 2.2): the user program
// runs one line per pass, so this paces the program. docs/dialects/gold-firmware.md, "Time".
#pragma once
#include <algorithm>
#include <cstdint>

#include "drive/axis.h"

namespace uprog::gold {

// Manual 2.2: the background "can jitter between 100 µsec and 1 msec", and "a higher sampling
// time [TS] means faster user program execution". The model: the servo interrupt takes 22.5 µs
// of the CPU every TS, and one background pass needs 100 µs of what is left, so a pass lasts
// 100 µs · TS / (TS − 22.5 µs) = 200 µs · TS / (2 · TS − 45 µs). The two constants put the
// drive's TS range (25..2000 µs) onto the manual's range: 1 ms at TS = 25, 181.818 µs at the
// default 50, 101.138 µs at 2000; the longer TS, the shorter the pass. Whole nanoseconds,
// rounded down, so the same TS always gives the same pacing.
constexpr uint64_t background_pass_ns(uint32_t servo_us) {
  const uint64_t ts = std::clamp(servo_us, drive::kMinPeriod_us, drive::kMaxPeriod_us);
  return 200'000 * ts / (2 * ts - 45);
}

// The pass a drive uses: `fixed_us` when the user fixed one (`--background-us`, the transcripts'
// `background`), else the model's for the servo period.
constexpr uint64_t background_pass_ns(uint32_t servo_us, uint32_t fixed_us) {
  return fixed_us != 0 ? uint64_t{fixed_us} * 1000 : background_pass_ns(servo_us);
}

}  // namespace uprog::gold
