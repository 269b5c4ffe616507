// Gold's homing event numbers (HM[3]) and what each means to the drive's homing process:
// immediate, the main home switch, the index, the limit switches and each digital input, with
// their edges (docs/dialects/gold.md, "Homing").
#pragma once
#include <cstdint>

#include "drive/homing.h"

namespace uprog::gold {

// Sets the event of `h` (trigger, switch, input, edge) for HM[3]=code; false when no event has
// that number (the caller answers 21, out of range).
bool set_home_event(int32_t code, drive::HomingSettings& h);

// The HM[3] number of the event `h` holds.
int32_t home_event_code(const drive::HomingSettings& h);

}  // namespace uprog::gold
