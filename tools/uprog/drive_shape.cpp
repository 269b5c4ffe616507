// The --axes and --servo-us options (drive_shape.h).
#include "drive_shape.h"

#include "drive/axis.h"

namespace uprog::cli {

void add_drive_shape_options(CLI::App* cmd, DriveShape& shape) {
  cmd->add_option("--axes", shape.axes, "the drive's axes (PDL's slave variables by axis)")
      ->check(CLI::Range(1u, controller::kMaxAxes))
      ->capture_default_str();
  cmd->add_option("--servo-us", shape.servo_us,
                  "every axis's servo period in microseconds (PDL's phase; default: the saved one)")
      ->check(CLI::Range(drive::kMinPeriod_us, drive::kMaxPeriod_us));
}

void apply(const DriveShape& shape, controller::ControllerOptions& options) {
  options.axes = shape.axes;
  options.servo_period_us = shape.servo_us;
}

}  // namespace uprog::cli
