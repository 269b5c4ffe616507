// The table of injectable fault names.
#include "drive/faults.h"

#include <array>

namespace uprog::drive {
namespace {
constexpr std::array kNames{
    FaultName{"feedback", kFaultFeedback},
    FaultName{"overcurrent", kFaultOvercurrent},
    FaultName{"velocity_error", kFaultVelocityError},
    FaultName{"following_error", kFaultFollowingError},
    FaultName{"undervoltage", kFaultUndervoltage},
    FaultName{"overvoltage", kFaultOvervoltage},
    FaultName{"short", kFaultShort},
    FaultName{"temperature", kFaultTemperature},
    FaultName{"speed_limit", kFaultSpeedLimit},
    FaultName{"position_limit", kFaultPositionLimit},
};
}  // namespace

std::span<const FaultName> fault_names() { return kNames; }

uint32_t fault_bits(std::string_view name) {
  for (const FaultName& f : kNames)
    if (f.name == name) return f.bits;
  return 0;
}

}  // namespace uprog::drive
