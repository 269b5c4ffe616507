// The S300's motion on the simulated axis (firmware.h): units (positions in counts ×
// PGEARI/PGEARO, speeds in rpm and ramps in ms from 0 to VLIM), jog (J), motion tasks (ORDER,
// MOVE, next task after FT ms).
#include <cmath>
#include <cstdlib>
#include <utility>

#include "dialects/st/firmware.h"
#include "drive/axis.h"

namespace uprog::st {
namespace {

// A rate or speed as the axis takes it: whole, at most int32 (NaN and below 1 give `low`).
int32_t to_axis(double v, double low = 1.0) {
  if (!(v >= low)) return static_cast<int32_t>(low);
  return v >= 2147483647.0 ? INT32_MAX : static_cast<int32_t>(v);
}

int32_t saturate(double v) {
  if (!(v > -2147483648.0)) return INT32_MIN;
  return v >= 2147483647.0 ? INT32_MAX : static_cast<int32_t>(v);
}

}  // namespace

// User units and counts: counts × PGEARI / PGEARO. The drive keeps a target between two counts
// where the gear does not divide (ORDER 192 49000 is 321126.4 counts) and rounds what it shows.
double Firmware::counts_exact(double user) const {
  const double in = values_.at("PGEARI"), out = values_.at("PGEARO");
  return in == 0 ? 0.0 : user * out / in;
}

int32_t Firmware::counts_of(int64_t user) const {
  return saturate(std::round(counts_exact(double(user))));
}

int32_t Firmware::user_of(double counts) const {
  const double in = values_.at("PGEARI"), out = values_.at("PGEARO");
  return out == 0 ? 0 : saturate(std::round(counts * in / out));
}

double Firmware::rpm_to_counts(double rpm) const {
  return rpm * axis_->parameters().counts_per_revolution() / 60.0;
}

// A ramp of `ms` from 0 to VLIM as an acceleration in counts/s².
double Firmware::ramp_counts_per_s2(int32_t ms) const {
  const double vlim = rpm_to_counts(values_.at("VLIM"));
  return vlim / (std::max(ms, 1) / 1000.0);
}

// The S300's limits on the axis (shared/spec/s300-drive.md; docs/dialects/st.md, "Motion"):
// VLIM bounds every speed command, VOSPD is F08's threshold on the actual speed, PEMAX F03's on
// the following error (0: off). The drive has no velocity-error fault: that check is off.
void Firmware::apply_limits() {
  drive::Parameters& p = axis_->parameters();
  const int32_t vlim = to_axis(std::round(rpm_to_counts(values_.at("VLIM"))), 0.0);
  p.velocity_high_counts_per_s = vlim;
  p.velocity_low_counts_per_s = -vlim;
  const int32_t vospd = to_axis(std::round(rpm_to_counts(values_.at("VOSPD"))), 0.0);
  p.speed_fault_high_counts_per_s = vospd;
  p.speed_fault_low_counts_per_s = -vospd;
  p.max_velocity_error_counts_per_s = INT32_MAX;
  const int32_t pemax = values_.at("PEMAX");
  p.max_position_error_counts =
      pemax == 0 ? INT32_MAX : to_axis(std::fabs(counts_exact(pemax)), 0.0);
}

// A motion command while the output stage is still switching on (EN's enable delay, ACTIVE
// already 1) waits for it, as the S300 takes the command and moves once it is ready.
bool Firmware::defer_until_ready(Deferred::Kind kind, int32_t a, int32_t b) {
  if (axis_->servo_ready()) return false;
  deferred_ = Deferred{kind, a, b};
  return true;
}

int32_t Firmware::jog(int32_t rpm, int32_t ms) {
  if (!axis_->motor_on()) return kErrNeedsEnabled;
  if (opmode_ != 0) return kErrOpmode;
  if (defer_until_ready(Deferred::kJog, rpm, ms)) return 0;
  apply_limits();
  drive::Parameters& p = axis_->parameters();
  p.accel_counts_per_s2 = to_axis(ramp_counts_per_s2(values_.at("ACC")));
  p.decel_counts_per_s2 = to_axis(ramp_counts_per_s2(values_.at("DEC")));
  const double vlim = values_.at("VLIM");
  const double v = std::round(rpm_to_counts(std::clamp(double(rpm), -vlim, vlim)));
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
  if (defer_until_ready(Deferred::kTask, nr, 0)) return 0;
  apply_limits();
  const MotionTask& t = it->second;
  const bool user_units = (t.c & (1 << 13)) != 0;
  const double distance = user_units ? counts_exact(t.p) : t.p;
  // Relative to the last target, kept exact while the axis still has it (else the axis' own).
  const double last = std::llround(target_counts_) == axis_->absolute_target()
                          ? target_counts_
                          : axis_->absolute_target();
  target_counts_ = (t.c & 1) != 0 ? last + distance : distance;
  drive::Parameters& p = axis_->parameters();
  const double vlim = rpm_to_counts(values_.at("VLIM"));
  const double speed = std::min(std::fabs(user_units ? counts_exact(t.v) : t.v), vlim);
  p.speed_counts_per_s = to_axis(std::round(speed));
  p.accel_counts_per_s2 = to_axis(speed / (std::max(t.acc, 1) / 1000.0));
  p.decel_counts_per_s2 = to_axis(speed / (std::max(t.dec, 1) / 1000.0));
  axis_->set_absolute_target_exact(target_counts_);
  if (axis_->begin() != drive::Status::kOk) return kErrTask;
  last_move_ = nr;
  next_pending_ = (t.c & (1 << 3)) != 0 && t.fn != 0;
  next_task_ = t.fn;
  next_at_ns_ = 0;
  return 0;
}

// MH (SERVOSTAR-family reference, "MH", "NREF", "DREF", "VREF"): NREF 0 and 6 take the
// position where the axis stands as the reference point; NREF 5 moves at VREF (user units/s) in
// DREF's direction (0 negative, 1 positive, 2 the nearer) to the feedback's next zero mark and
// takes it. The reference point reads ROFFS. The searching types 1 to 4, 7 and 9 are
// homing.cpp's; 8 (an absolute SSI encoder's position) and 10 to 20 (described nowhere): MH
// refuses them (3), docs/dialects/st.md.
int32_t Firmware::start_homing() {
  if (opmode_ != 8) return kErrOpmode;
  if (!axis_->motor_on()) return kErrNeedsEnabled;
  const int32_t nref = values_.at("NREF");
  if ((nref >= 1 && nref <= 4) || nref == 7 || nref == 9) {
    const int32_t code = start_switch_homing(nref);
    if (code == 0) reference_set_ = false;  // until this homing sets it
    return code;
  }
  if (nref != 0 && nref != 5 && nref != 6) return kErrRange;
  reference_set_ = false;
  end_homing();
  next_pending_ = false;
  refpos_motor_ = axis_->motor_state().position_counts;  // REFPOS: where it started
  if (nref != 5) {
    set_reference();
    return 0;
  }
  if (!axis_->servo_ready()) return kErrNeedsEnabled;
  apply_limits();
  const double cpr = axis_->parameters().counts_per_revolution();
  const double motor = axis_->motor_state().position_counts, offset = axis_->index_offset();
  const double below = offset + std::floor((motor - offset) / cpr) * cpr;
  const double above = below == motor ? motor : below + cpr;
  const int32_t dref = values_.at("DREF");
  const double mark = dref == 1   ? above
                      : dref == 0 ? below
                                  : (motor - below <= above - motor ? below : above);
  const double speed =
      std::min(std::fabs(counts_exact(values_.at("VREF"))), rpm_to_counts(values_.at("VLIM")));
  drive::Parameters& p = axis_->parameters();
  p.speed_counts_per_s = to_axis(speed);
  p.accel_counts_per_s2 = p.decel_counts_per_s2 = to_axis(ramp_counts_per_s2(values_.at("ACC")));
  target_counts_ = axis_->position_exact() + (mark - motor);
  axis_->set_absolute_target_exact(target_counts_);
  if (axis_->begin() != drive::Status::kOk) return kErrNeedsEnabled;
  homing_ = true;
  homing_mark_ = mark;
  return 0;
}

// The motor position `at_motor` (motor counts) becomes the reference point: it reads ROFFS.
// SETREF and NREF 0 take the present position, NREF 5 the zero mark it went to.
void Firmware::set_reference(double at_motor) {
  const double roffs = counts_exact(values_.at("ROFFS"));
  const double motor = axis_->motor_state().position_counts;
  const double shift = roffs + (motor - at_motor) - axis_->position_exact();
  axis_->set_position(saturate(std::round(roffs + (motor - at_motor))));
  target_counts_ += shift;
  homing_ = false;
  reference_set_ = true;
}

void Firmware::set_reference() { set_reference(axis_->motor_state().position_counts); }

// PRD: the feedback's position within one turn, 20 bits (0..1048575), whatever PFB says.
int32_t Firmware::feedback_within_turn() const {
  return within_turn(axis_->motor_state().position_counts);
}

// A motor position within its turn in 20 bits (PRD, REFPOS).
int32_t Firmware::within_turn(double motor) const {
  const double cpr = axis_->parameters().counts_per_revolution();
  const double within = motor - std::floor(motor / cpr) * cpr;
  // A position a whole step of the 20 bits up to the arithmetic's noise (a target reached by
  // way of an offset, 66535.99999999 for 66536) reads that step.
  const double steps = std::floor(within * 1048576.0 / cpr + 1e-6);
  return std::clamp(static_cast<int32_t>(steps), 0, 1048575);
}

// The axis' own stop ramp (SD) stays for its other stops (homing's).
void Firmware::stop_axis_with(double decel) { axis_->stop_with(to_axis(decel)); }

// The spec's STOP: "decelerate (task's d, else DECSTOP)"; a task's d was set when it began.
void Firmware::stop_motion() {
  const bool task = axis_->motion_kind() == drive::Axis::MotionKind::kPointToPoint && !homing_ &&
                    switch_homing_.phase == SwitchHoming::kIdle;
  const double task_decel = axis_->parameters().decel_counts_per_s2;
  next_pending_ = false;
  end_homing();
  jog_until_ns_ = 0;
  stop_axis_with(task ? task_decel : ramp_counts_per_s2(values_.at("DECSTOP")));
}

// Each axis step: a jog's time ends; a finished task with a next one starts it after FT ms.
void Firmware::step_motion() {
  if (deferred_.kind != Deferred::kNone && !axis_->motor_on()) deferred_ = Deferred{};  // a fault
  if (deferred_.kind != Deferred::kNone && axis_->servo_ready()) {
    const Deferred d = std::exchange(deferred_, Deferred{});
    if (d.kind == Deferred::kJog)
      jog(d.a, d.b);
    else
      start_task(d.a);
  }
  if (jog_until_ns_ != 0 && runtime_.now_ns() >= jog_until_ns_) {
    jog_until_ns_ = 0;
    stop_axis_with(ramp_counts_per_s2(values_.at("DEC")));  // J v t: its ramps are ACC and DEC
  }
  // Each is a call only while it has work (the usual cycle has neither): a search under way,
  // OPMODE 1 or the speed it last commanded to forget.
  if (switch_homing_.phase != SwitchHoming::kIdle) step_switch_homing();
  if (opmode_ == 1 || analog_rpm_) step_analog_speed();
  if (homing_ && !axis_->profiler_moving()) {
    if (axis_->motor_on()) set_reference(homing_mark_);
    homing_ = false;
  }
  if (!next_pending_ || axis_->profiler_moving()) return;
  const MotionTask& t = tasks_[last_move_];
  if (next_at_ns_ == 0) next_at_ns_ = runtime_.now_ns() + uint64_t(std::max(t.ft, 0)) * 1'000'000;
  if (runtime_.now_ns() < next_at_ns_) return;
  next_pending_ = false;
  start_task(next_task_);
}

}  // namespace uprog::st
