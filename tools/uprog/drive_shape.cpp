// The --axes, --servo-us and --background-us options (drive_shape.h).
#include "drive_shape.h"

#include "drive/axis.h"

namespace uprog::cli {

void add_drive_shape_options(Options& cmd, DriveShape& shape) {
  cmd.option("--axes", shape.axes, "the drive's axes (PDL's slave variables by axis)")
      .within(1u, controller::kMaxAxes)
      .show_default();
  cmd.option("--servo-us", shape.servo_us,
             "every axis's servo period in microseconds (PDL's phase; default: the saved one)")
      .within(drive::kMinPeriod_us, drive::kMaxPeriod_us);
  cmd.option("--background-us", shape.background_us,
             "Gold: a fixed background pass in microseconds, one program line each (default: "
             "from TS, 181.818 at TS=50; docs/dialects/gold-firmware.md)")
      .within(1u, 1'000'000u);
}

void apply(const DriveShape& shape, controller::ControllerOptions& options) {
  options.axes = shape.axes;
  options.servo_period_us = shape.servo_us;
  options.timing.background_us = shape.background_us;
}

}  // namespace uprog::cli
