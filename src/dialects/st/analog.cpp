// The S300's analog inputs SW1 and SW2 (firmware.h; docs/dialects/st.md, "Analog speed"): their
// levels are the world's (a transcript's `analog N = MV`), ANIN1/ANIN2 read them, and OPMODE 1
// runs the motor at (ANIN1 + ANOFF1) / 10 V × VSCALE1 rpm, within VLIM, when ANCNFG (as the
// last boot took it) makes SW1 the speed setpoint.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "dialects/st/firmware.h"
#include "drive/axis.h"

namespace uprog::st {
namespace {

constexpr int32_t kFullScaleMv = 10'000;  // the inputs' range, ±10 V (the reference's ANIN1)

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

}  // namespace

// `analog N = MV` (N 1 for SW1, 2 for SW2; `analog = MV` is SW1): the input's level in mV.
bool Firmware::world_directive(std::string_view name, std::string_view arg, std::string& failure) {
  if (name != "analog") return false;
  const size_t eq = arg.find('=');
  const std::string_view which = trimmed(arg.substr(0, std::min(eq, arg.size())));
  const std::string_view level = eq == std::string_view::npos ? "" : trimmed(arg.substr(eq + 1));
  int32_t mv = 0;
  const auto [end, ec] = std::from_chars(level.data(), level.data() + level.size(), mv);
  const bool number = !level.empty() && ec == std::errc() && end == level.data() + level.size();
  if ((which != "" && which != "1" && which != "2") || !number) {
    failure = "analog needs 'analog N = MV' (N 1 or 2, an integer in mV)";
    return true;
  }
  analog_mv_[which == "2" ? 1 : 0] = mv;
  return true;
}

int32_t Firmware::analog_input_mv(int n) const {
  return std::clamp(analog_mv_[n == 2 ? 1 : 0], -kFullScaleMv, kFullScaleMv);
}

// ANCNFG 0 and 1 both make SW1 OPMODE 1's speed setpoint (the reference's "ANCNFG" page); the
// speed ramps as a jog's (ACC, DEC) and follows the input each axis step.
void Firmware::step_analog_speed() {
  if (opmode_ != 1 || ancnfg_ > 1 || !axis_->motor_on() || !axis_->servo_ready()) {
    analog_rpm_.reset();
    return;
  }
  const double mv = analog_input_mv(1) + values_.at("ANOFF1");
  const double vlim = values_.at("VLIM");
  const double rpm = std::clamp(mv / kFullScaleMv * values_.at("VSCALE1"), -vlim, vlim);
  if (analog_rpm_ == rpm) return;
  analog_rpm_ = rpm;
  apply_limits();
  drive::Parameters& p = axis_->parameters();
  p.accel_counts_per_s2 =
      static_cast<int32_t>(std::clamp(ramp_counts_per_s2(values_.at("ACC")), 1.0, 2147483647.0));
  p.decel_counts_per_s2 =
      static_cast<int32_t>(std::clamp(ramp_counts_per_s2(values_.at("DEC")), 1.0, 2147483647.0));
  axis_->set_jog_velocity(static_cast<int32_t>(std::round(rpm_to_counts(rpm))));
  axis_->begin();
}

}  // namespace uprog::st
