// The S300's motion on the simulated axis (firmware.h): units (positions in counts ×
// PGEARI/PGEARO, speeds in rpm and ramps in ms from 0 to VLIM), jog (J), motion tasks (ORDER,
// MOVE, next task after FT ms).
#include <cmath>
#include <cstdlib>

#include "dialects/st/firmware.h"
#include "drive/axis.h"

namespace uprog::st {
namespace {

// A rate or speed as the axis takes it: whole, at most int32 (NaN and below 1 give `low`).
int32_t to_axis(double v, double low = 1.0) {
  if (!(v >= low)) return static_cast<int32_t>(low);
  return v >= 2147483647.0 ? INT32_MAX : static_cast<int32_t>(v);
}

}  // namespace

int32_t Firmware::counts_of(int64_t user) const {
  const int64_t in = values_.at("PGEARI"), out = values_.at("PGEARO");
  return static_cast<int32_t>(in == 0 ? 0 : user * out / in);
}

int32_t Firmware::user_of(int64_t counts) const {
  const int64_t in = values_.at("PGEARI"), out = values_.at("PGEARO");
  return static_cast<int32_t>(out == 0 ? 0 : counts * in / out);
}

double Firmware::rpm_to_counts(double rpm) const { return rpm * axis_->parameters().counts_per_revolution() / 60.0; }

// A ramp of `ms` from 0 to VLIM as an acceleration in counts/s².
double Firmware::ramp_counts_per_s2(int32_t ms) const {
  const double vlim = rpm_to_counts(values_.at("VLIM"));
  return vlim / (std::max(ms, 1) / 1000.0);
}

int32_t Firmware::jog(int32_t rpm, int32_t ms) {
  if (!axis_->motor_on()) return kErrNeedsEnabled;
  if (opmode_ != 0) return kErrOpmode;
  drive::Parameters& p = axis_->parameters();
  p.accel_counts_per_s2 = to_axis(ramp_counts_per_s2(values_.at("ACC")));
  p.decel_counts_per_s2 = to_axis(ramp_counts_per_s2(values_.at("DEC")));
  const double v = rpm_to_counts(rpm);
  axis_->set_jog_velocity(v < 0 ? -to_axis(-v, 0.0) : to_axis(v, 0.0));
  axis_->begin();
  jog_until_ns_ = ms > 0 ? runtime_.now_ns() + uint64_t(ms) * 1'000'000 : 0;
  return 0;
}

int32_t Firmware::start_task(int32_t nr) {
  if (opmode_ != 8) return kErrOpmode;
  if (!axis_->motor_on()) return kErrNeedsEnabled;
  auto it = tasks_.find(nr);
  if (it == tasks_.end() || !it->second.defined) return kErrTask;
  const MotionTask& t = it->second;
  const bool user_units = (t.c & (1 << 13)) != 0;
  const int64_t distance = user_units ? counts_of(t.p) : t.p;
  target_counts_ = (t.c & 1) != 0 ? axis_->absolute_target() + distance : distance;
  drive::Parameters& p = axis_->parameters();
  const double speed = user_units ? std::abs(static_cast<double>(counts_of(t.v))) : std::abs(static_cast<double>(t.v));
  p.speed_counts_per_s = to_axis(speed);
  p.accel_counts_per_s2 = to_axis(speed / (std::max(t.acc, 1) / 1000.0));
  p.decel_counts_per_s2 = to_axis(speed / (std::max(t.dec, 1) / 1000.0));
  axis_->set_absolute_target(static_cast<int32_t>(target_counts_));
  if (axis_->begin() != drive::Status::kOk) return kErrTask;
  last_move_ = nr;
  next_pending_ = (t.c & (1 << 3)) != 0 && t.fn != 0;
  next_task_ = t.fn;
  next_at_ns_ = 0;
  return 0;
}

// Each axis step: a jog's time ends; a finished task with a next one starts it after FT ms.
void Firmware::step_motion() {
  if (jog_until_ns_ != 0 && runtime_.now_ns() >= jog_until_ns_) {
    jog_until_ns_ = 0;
    axis_->stop();
  }
  if (!next_pending_ || axis_->profiler_moving()) return;
  const MotionTask& t = tasks_[last_move_];
  if (next_at_ns_ == 0) next_at_ns_ = runtime_.now_ns() + uint64_t(std::max(t.ft, 0)) * 1'000'000;
  if (runtime_.now_ns() < next_at_ns_) return;
  next_pending_ = false;
  start_task(next_task_);
}

}  // namespace uprog::st
