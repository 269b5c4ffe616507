// The simulated drive's shape for `uprog run` and `uprog sim`: how many axes, and their servo
// period (PDL's phase), as a transcript's `drive axes=N phase_us=N` sets them; Gold's background
// pass, as its `background N` does.
#pragma once
#include <cstdint>

#include "commands.h"
#include "controller/controller.h"

namespace uprog::cli {

struct DriveShape {
  uint32_t axes = 1;
  uint32_t servo_us = 0;       // 0: the saved period, else the axis's default
  uint32_t background_us = 0;  // 0: the dialect's own pace (Gold: from TS, manual 2.2)
};

// Adds `--axes N`, `--servo-us N` and `--background-us N` to `cmd`, stored in `shape`.
void add_drive_shape_options(Options& cmd, DriveShape& shape);
void apply(const DriveShape& shape, controller::ControllerOptions& options);

}  // namespace uprog::cli
