// The servo cycle: inputs, enable delay, profile and smoothing, limits, loops, motor, faults,
// the target window and homing.
#include "drive/axis.h"

#include <algorithm>
#include <cmath>

#include "drive/faults.h"
#include "drive/inputs.h"

namespace uprog::drive {
namespace {

double floor_mod(double a, double m) { return a - m * std::floor(a / m); }

}  // namespace

Axis::Axis(const MotorModel& motor)
    : motor_(motor), accel_per_amp_counts_per_s2_(motor.accel_per_amp_counts_per_s2()) {
  smooth_position_.reset(1, 0.0);
  smooth_velocity_.reset(1, 0.0);
  smooth_accel_.reset(1, 0.0);
}

// ---------------------------------------------------------------- parameters

Status Axis::load_parameters(const Parameters& params) {
  if (motor_on_) return Status::kMotorOn;
  params_ = params;
  for (int n = 1; n <= kInputCount; ++n) input_was_active_[n - 1] = input_active(n);
  inputs_changed_ = true;
  return Status::kOk;
}

Status Axis::set_unit_mode(int32_t mode) {
  if (mode != 1 && mode != 2 && mode != 5) return Status::kOutOfRange;
  if (motor_on_) return Status::kMotorOn;
  params_.unit_mode = mode;
  return Status::kOk;
}

Status Axis::set_input_logic(int n, int32_t logic) {
  if (n < 1 || n > kInputCount || !valid_input_logic(logic)) return Status::kOutOfRange;
  params_.input_logic[n - 1] = logic;
  // A change of function is not an edge: remember the new logical state as the old one.
  input_was_active_[n - 1] = input_active(n);
  inputs_changed_ = true;
  return Status::kOk;
}

Status Axis::set_period_us(int32_t period_us) {
  if (period_us < static_cast<int32_t>(kMinPeriod_us) ||
      period_us > static_cast<int32_t>(kMaxPeriod_us))
    return Status::kOutOfRange;
  params_.servo_period_us = period_us;
  return Status::kOk;
}

Status Axis::set_counts_per_revolution(int32_t counts) {
  if (counts < 6) return Status::kOutOfRange;  // the reference's CA[18] range starts at 6
  if (motor_on_) return Status::kMotorOn;
  params_.commutation[kCountsPerRevolutionIndex - 1] = counts;
  return Status::kOk;
}

// ---------------------------------------------------------------- enable

Status Axis::set_motor_on(bool on) {
  if (!on) {
    motor_off();
    return Status::kOk;
  }
  if (fault_causes_ != 0) return Status::kFaultLatched;
  for (int n = 1; n <= kInputCount; ++n)
    if (input_function(params_.input_logic[n - 1]) == InputFunction::kInhibit && input_active(n))
      return Status::kInhibitActive;
  if (motor_on_) return Status::kOk;
  fault_bits_ = 0;
  power_stage_codes_ = 0;
  motor_on_ = true;
  servo_ready_ = false;
  enable_elapsed_us_ = 0;
  // A program may set a target and begin during the enable delay (manual 2.18: MO=1, PR=..., BG):
  // that target is relative to where the motor is now, and it survives the loop closing.
  target_internal_ = raw_.position_counts;
  pa_counts_ = internal_to_user(target_internal_);
  target_set_while_enabling_ = false;
  return Status::kOk;
}

void Axis::motor_off() {
  motor_on_ = false;
  servo_ready_ = false;
  moving_ = false;
  ramping_ = false;
  pt_active_ = false;
  motion_kind_ = MotionKind::kNone;
  has_target_ = false;
  in_window_us_ = -1;
  current_command_a_ = 0.0;
  velocity_command_counts_per_s_ = 0.0;
}

void Axis::latch_fault(uint32_t bits) {
  if (fault_bits_ == 0) pending_events_ |= kEventFault;
  fault_bits_ |= bits;
  if ((bits & kFaultPowerStage) != 0) power_stage_codes_ |= 1u << power_stage_code(bits);
  motor_off();
}

void Axis::clear_faults() {
  fault_bits_ &= fault_causes_;
  const uint32_t code = power_stage_code(fault_causes_);
  power_stage_codes_ = code != 0 ? 1u << code : 0u;
}

bool Axis::inject_fault(std::string_view name, bool persistent) {
  const uint32_t bits = fault_bits(name);
  if (bits == 0) return false;
  if (persistent) fault_causes_ |= bits;
  latch_fault(bits);
  return true;
}

void Axis::clear_fault_cause(std::string_view name) { fault_causes_ &= ~fault_bits(name); }

// ---------------------------------------------------------------- motion commands

double Axis::user_to_internal(int64_t user) const {
  return static_cast<double>(user) - offset_counts_;
}

int32_t Axis::internal_to_user_slow(double exact) const {
  const double user = std::round(exact);
  if (modulo_active()) {
    const double low = params_.modulo_low_counts;
    const double range = static_cast<double>(params_.modulo_high_counts) - low;
    return static_cast<int32_t>(low + floor_mod(user - low, range));
  }
  return static_cast<int32_t>(
      static_cast<uint32_t>(static_cast<int64_t>(floor_mod(user, 4294967296.0))));
}

void Axis::set_absolute_target(int32_t target_counts) {
  pa_counts_ = target_counts;
  if (motor_on_ && !servo_ready_) target_set_while_enabling_ = true;
  pending_ = Pending::kMove;
  if (modulo_active()) {
    // Go the shortest way round to the equivalent of the target.
    const double range =
        static_cast<double>(params_.modulo_high_counts) - params_.modulo_low_counts;
    const double here_user = raw_.position_counts + offset_counts_;
    const double delta = floor_mod(target_counts - here_user + range / 2.0, range) - range / 2.0;
    target_internal_ = raw_.position_counts + delta;
    return;
  }
  target_internal_ = user_to_internal(target_counts);
}

void Axis::set_absolute_target_exact(double target_counts) {
  set_absolute_target(
      static_cast<int32_t>(std::clamp(std::round(target_counts), -2147483648.0, 2147483647.0)));
  if (!modulo_active()) target_internal_ = target_counts - offset_counts_;
}

void Axis::set_relative_move(int32_t distance_counts) {
  pr_counts_ = distance_counts;
  pending_ = Pending::kMove;
  if (motor_on_ && !servo_ready_) target_set_while_enabling_ = true;
  target_internal_ += distance_counts;
}

void Axis::set_jog_velocity(int32_t velocity_counts_per_s) {
  params_.jog_velocity_counts_per_s = velocity_counts_per_s;
  pending_ = Pending::kJog;
}

void Axis::set_pt_start(int32_t index) {
  pt_start_ = index;
  pending_ = Pending::kPt;
}

int32_t Axis::pt_index() const { return pt_active_ ? pt_executing_ : pt_start_; }

void Axis::start_profile(const Profile& profile, bool stopping) {
  profile_ = profile;
  profile_duration_s_ = profile.duration_s();
  stopping_ = stopping;
  profile_start_cycle_ = cycles_;
  pt_active_ = false;
  ramping_ = true;
  in_window_us_ = -1;
  if (!moving_) {
    // A new motion from rest takes the current SF; while moving the window stays as it is.
    const double window_us = params_.smoothing_ms * 1000.0;
    const auto length = std::max<uint32_t>(
        1u, static_cast<uint32_t>(std::lround(window_us / params_.servo_period_us)));
    smooth_position_.reset(length, raw_.position_counts);
    smooth_velocity_.reset(length, raw_.velocity_counts_per_s);
    smooth_accel_.reset(length, 0.0);
  }
  moving_ = true;
}

Status Axis::begin() {
  const Status status = begin_motion();
  if (status == Status::kOk) recorder_.on_begin();
  return status;
}

Status Axis::begin_motion() {
  if (!motor_on_) return Status::kMotorOff;
  if (params_.unit_mode == 1) return Status::kModeNotSupported;
  if (pending_ == Pending::kPt) {
    if (params_.unit_mode != 5) return Status::kModeNotSupported;
    if (!pt_can_start(pt_, pt_start_)) return Status::kBadStartData;
  }
  stopped_by_limit_ = false;
  ends_at_limit_ = false;
  has_target_ = false;
  const MotionLimits limits{static_cast<double>(params_.speed_counts_per_s),
                            static_cast<double>(params_.accel_counts_per_s2),
                            static_cast<double>(params_.decel_counts_per_s2)};
  const double vh = std::max(1.0, static_cast<double>(params_.velocity_high_counts_per_s));
  const double vl = std::min(-1.0, static_cast<double>(params_.velocity_low_counts_per_s));
  if (pending_ == Pending::kPt && params_.unit_mode == 5) {
    // The PT motion runs in advance_pt; the smoothing window does not apply to it.
    start_profile(plan_stop(raw_.position_counts, 0.0, 1.0), false);
    pt_active_ = true;
    motion_kind_ = MotionKind::kPt;
    pt_executing_ = pt_start_;
    pt_offset_counts_ = offset_counts_;
    return Status::kOk;
  }
  if (params_.unit_mode == 2 || pending_ == Pending::kJog) {
    motion_kind_ = MotionKind::kJog;
    const double jog = std::clamp(static_cast<double>(params_.jog_velocity_counts_per_s), vl, vh);
    if (params_.unit_mode == 2 && params_.profiler_mode == 0) {
      // No profiler (PM=0): the reference is the jog velocity at once.
      Profile step_to_jog;
      step_to_jog.start_position_counts = raw_.position_counts;
      step_to_jog.start_velocity_counts_per_s = jog;
      step_to_jog.end_velocity_counts_per_s = jog;
      start_profile(step_to_jog, false);
      return Status::kOk;
    }
    if (params_.unit_mode == 5 && !modulo_active() && jog != 0.0) {
      // A position-mode jog ends at the software limit in its direction.
      MotionLimits to_limit = limits;
      to_limit.speed_counts_per_s = std::abs(jog);
      const double limit = jog > 0 ? user_to_internal(params_.position_high_counts)
                                   : user_to_internal(params_.position_low_counts);
      ends_at_limit_ = true;  // a position-mode jog can only end at the software limit
      start_profile(plan_move(raw_.position_counts, raw_.velocity_counts_per_s, limit, to_limit),
                    false);
    } else {
      start_profile(plan_jog(raw_.position_counts, raw_.velocity_counts_per_s, jog, limits), false);
    }
    return Status::kOk;
  }
  motion_kind_ = MotionKind::kPointToPoint;
  double target = target_internal_;
  if (!modulo_active()) {
    target = std::clamp(target, user_to_internal(params_.position_low_counts),
                        user_to_internal(params_.position_high_counts));
    ends_at_limit_ = target != target_internal_;
  }
  MotionLimits move = limits;
  move.speed_counts_per_s =
      std::min(move.speed_counts_per_s, target >= raw_.position_counts ? vh : -vl);
  start_profile(plan_move(raw_.position_counts, raw_.velocity_counts_per_s, target, move), false);
  has_target_ = true;
  return Status::kOk;
}

void Axis::stop_with(double decel_counts_per_s2) {
  if (!moving_) return;
  start_profile(plan_stop(raw_.position_counts, raw_.velocity_counts_per_s, decel_counts_per_s2),
                true);
  has_target_ = false;  // a stopped motion has no target to settle at: MS stays 1
  ends_at_limit_ = false;
}

void Axis::stop() { stop_with(params_.stop_decel_counts_per_s2); }

// ---------------------------------------------------------------- feedback

void Axis::set_position(int32_t position_counts) {
  offset_counts_ = position_counts - std::round(motor_state_.position_counts);
}

int32_t Axis::motion_status() const {
  if (!servo_ready_) return 3;  // the motor is off (or still enabling): Gold's "motor off"
  switch (params_.unit_mode) {
    case 1:
      return 1;  // no software motion in current mode
    case 2:
      return ramping_ ? 2 : 1;  // the reference differs from the JV target while ramping
    default:
      break;
  }
  if (moving_) return 2;
  const bool settled =
      has_target_ && in_window_us_ >= static_cast<int64_t>(params_.target_time_ms) * 1000;
  return settled ? 0 : 1;
}

uint32_t Axis::status_register() const {
  uint32_t sr = 0;
  const uint32_t stage = power_stage_code(fault_bits_);
  if (stage != 0) sr |= kSrDriveProblem | (stage << kSrPowerStageShift);
  if (motor_on_) sr |= kSrMotorOn;
  if (fault_bits_ != 0) sr |= kSrMotorFailure;
  sr |= (static_cast<uint32_t>(params_.unit_mode) & 7u) << kSrUnitModeShift;
  if (homing_.armed()) sr |= kSrHoming;
  if (above_continuous_s_ > kPeakCurrentTime_s) sr |= kSrCurrentLimited;
  sr |= kSrSafeTorqueOff1 | kSrSafeTorqueOff2;
  if (params_.reference_mode != 0) sr |= kSrReferenceMode;
  if (stopped_by_limit_) sr |= kSrStoppedByLimit;
  return sr;
}

// ---------------------------------------------------------------- I/O

void Axis::set_input_level(int n, bool high) {
  if (n < 1 || n > kInputCount) return;
  remove_position_switch(n);
  set_level_bit(n, high);
  inputs_changed_ = true;
}

bool Axis::input_level(int n) const { return n >= 1 && n <= kInputCount && level_bit(n); }

void Axis::place_position_switch(int n, double from_counts, double to_counts) {
  if (n < 1 || n > kInputCount) return;
  switches_[n - 1] = {true, std::min(from_counts, to_counts), std::max(from_counts, to_counts)};
  any_switch_ = true;
  follow_position_switches();
}

void Axis::remove_position_switch(int n) {
  if (n < 1 || n > kInputCount || !switches_[n - 1].placed) return;
  switches_[n - 1].placed = false;
  any_switch_ = false;
  for (const PositionSwitch& sw : switches_) any_switch_ = any_switch_ || sw.placed;
}

void Axis::place_world(const World& world) {
  input_levels_ = world.input_levels;
  switches_ = world.switches;
  any_switch_ = false;
  for (const PositionSwitch& sw : switches_) any_switch_ = any_switch_ || sw.placed;
  index_offset_counts_ = world.index_offset_counts;
  end_stops_ = world.end_stops;
  follow_position_switches();
  for (int n = 1; n <= kInputCount; ++n) input_was_active_[n - 1] = input_active(n);
  inputs_changed_ = true;  // the next scan summarises the limits and inhibits that hold
}

void Axis::follow_position_switches() {
  const double at = motor_state_.position_counts;
  for (int n = 1; n <= kInputCount; ++n) {
    const PositionSwitch& sw = switches_[n - 1];
    if (!sw.placed) continue;
    const bool high = at >= sw.from_counts && at <= sw.to_counts;
    if (high == level_bit(n)) continue;
    set_level_bit(n, high);
    inputs_changed_ = true;
  }
}

void Axis::place_end_stops(double low_counts, double high_counts) {
  end_stops_ = {true, std::min(low_counts, high_counts), std::max(low_counts, high_counts)};
  meet_end_stops();
}

// An inelastic stop: the load stands at the stop and keeps no speed toward it.
void Axis::meet_end_stops() {
  MotorState& m = motor_state_;
  if (m.position_counts < end_stops_.low_counts) {
    m.position_counts = end_stops_.low_counts;
    m.velocity_counts_per_s = std::max(m.velocity_counts_per_s, 0.0);
  } else if (m.position_counts > end_stops_.high_counts) {
    m.position_counts = end_stops_.high_counts;
    m.velocity_counts_per_s = std::min(m.velocity_counts_per_s, 0.0);
  }
}

bool Axis::input_active(int n) const {
  if (n < 1 || n > kInputCount) return false;
  return drive::input_active(params_.input_logic[n - 1], level_bit(n));
}

uint32_t Axis::input_port() const {
  uint32_t bits = 0;
  for (int n = 1; n <= kInputCount; ++n) {
    const auto i = static_cast<size_t>(n - 1);
    if (level_bit(n)) bits |= 1u << (kIpLevelShift + static_cast<uint32_t>(n) - 1);
    if (!input_active(n)) continue;
    const InputFunction f = input_function(params_.input_logic[i]);
    if (f == InputFunction::kGeneralPurpose) bits |= kIpGeneralPurpose1 << (n - 1);
    bits |= input_function_bit(f);
  }
  return bits;
}

void Axis::set_output(int n, bool on) {
  if (n < 1 || n > kOutputCount) return;
  const uint32_t bit = 1u << (n - 1);
  outputs_ = on ? (outputs_ | bit) : (outputs_ & ~bit);
}

// ---------------------------------------------------------------- the servo cycle

uint32_t Axis::scan_inputs() {
  uint32_t events = 0;
  for (int n = 1; n <= kInputCount; ++n) {
    const int32_t logic = params_.input_logic[n - 1];
    const bool active = input_active(n);
    // Nothing to do for an input that did not change, unless it is an active inhibit.
    if (active == input_was_active_[n - 1] &&
        !(active && input_function(logic) == InputFunction::kInhibit))
      continue;
    const bool rose = active && !input_was_active_[n - 1];
    const bool fell = !active && input_was_active_[n - 1];
    input_was_active_[n - 1] = active;
    if (rose) inputs_rose_ |= 1u << (n - 1);
    if (fell) inputs_fell_ |= 1u << (n - 1);
    switch (input_function(logic)) {
      case InputFunction::kInhibit:
        if (active && motor_on_) motor_off();
        if (fell) events |= kEventInhibitReleased;
        break;
      case InputFunction::kGeneralPurpose:
        if (rose) events |= general_input_event(n);
        break;
      case InputFunction::kReverseLimit:
        if (rose) events |= kEventReverseLimit;
        break;
      case InputFunction::kForwardLimit:
        if (rose) events |= kEventForwardLimit;
        break;
      case InputFunction::kBegin:
        if (rose) {
          events |= kEventBegin;
          (void)begin();  // the event is reported even when the BG itself is refused
        }
        break;
      case InputFunction::kHome:
        if (rose) home_input_rose_ = true;  // the home event is step_homing's to decide
        break;
      case InputFunction::kHardStop:
        if (rose) events |= kEventHardStop;
        break;
      case InputFunction::kSoftStop:
      case InputFunction::kAbort:
        if (rose && moving_ && !stopping_) {
          stop_with(params_.stop_decel_counts_per_s2);
          stopped_by_limit_ = true;
        }
        break;
      case InputFunction::kIgnore:
      case InputFunction::kAuxHome:
        break;
    }
  }
  inputs_changed_ = false;
  inhibit_active_ = forward_limit_active_ = reverse_limit_active_ = hard_stop_active_ = false;
  for (int n = 1; n <= kInputCount; ++n) {
    if (!input_was_active_[n - 1]) continue;
    switch (input_function(params_.input_logic[n - 1])) {
      case InputFunction::kInhibit:
        inhibit_active_ = true;
        break;
      case InputFunction::kForwardLimit:
        forward_limit_active_ = true;
        break;
      case InputFunction::kReverseLimit:
        reverse_limit_active_ = true;
        break;
      case InputFunction::kHardStop:
        hard_stop_active_ = true;
        break;
      default:
        break;
    }
  }
  return events;
}

// Limit switches stop motion toward them and hard stop stops all motion, with SD.
void Axis::enforce_limits() {
  // The flags are scan_inputs' summary of the inputs as this cycle found them.
  const bool block_forward = forward_limit_active_, block_reverse = reverse_limit_active_,
             hard_stop = hard_stop_active_;
  if (!moving_ || stopping_ || !(hard_stop || block_forward || block_reverse)) return;
  const ProfileSample end = profile_.final_state();
  double heading = raw_.velocity_counts_per_s;
  if (heading == 0.0)
    heading = end.velocity_counts_per_s + (end.position_counts - raw_.position_counts);
  if (hard_stop || (block_forward && heading > 0.0) || (block_reverse && heading < 0.0)) {
    stop_with(params_.stop_decel_counts_per_s2);
    stopped_by_limit_ = true;
  }
}

void Axis::advance_pt() {
  const uint64_t cycles = cycles_ - profile_start_cycle_;
  const PtSample p = sample_pt(pt_, pt_start_, cycles, dt_s());
  pt_executing_ = p.index;
  const double offset = pt_offset_counts_;
  if (p.ended) {
    // The end of a non-cyclic PT motion: to a complete stop with SD from the last segment's speed.
    const double end = p.position_counts - offset;
    const double speed = cycles == 0 ? 0.0 : raw_.velocity_counts_per_s;
    start_profile(plan_stop(end, speed, params_.stop_decel_counts_per_s2), true);
    raw_ = sample(profile_, 0.0);
    ref_ = raw_;
    return;
  }
  raw_ = {p.position_counts - offset, p.velocity_counts_per_s, 0.0};
  ref_ = raw_;
}

void Axis::advance_profile() {
  if (!moving_) return;
  const double t_s = static_cast<double>(cycles_ - profile_start_cycle_) * dt_s();
  if (pt_active_) {
    advance_pt();
    return;
  }
  raw_ = sample(profile_, t_s);
  ramping_ = t_s < profile_duration_s_;
  const bool profile_done = t_s >= profile_duration_s_ && raw_.velocity_counts_per_s == 0.0;
  if (profile_done) raw_ = profile_.final_state();
  // The three windows always have one length; without smoothing (SF=0) a window of one sample
  // returns its sample and is always settled, so the reference is the profile itself.
  const bool smoothing = smooth_position_.length() != 1;
  if (smoothing) {
    ref_.position_counts = smooth_position_.push(raw_.position_counts);
    ref_.velocity_counts_per_s = smooth_velocity_.push(raw_.velocity_counts_per_s);
    ref_.accel_counts_per_s2 = smooth_accel_.push(raw_.accel_counts_per_s2);
  } else {
    ref_ = raw_;
  }
  const bool settled = !smoothing || (smooth_position_.settled() && smooth_velocity_.settled() &&
                                      smooth_accel_.settled());
  if (!settled) ramping_ = true;
  if (profile_done && settled) {
    moving_ = false;
    ramping_ = false;
    if (ends_at_limit_) stopped_by_limit_ = true;
    ref_ = raw_;
  }
}

double Axis::current_limit_a() {
  const double peak = params_.peak_current_a;
  const double continuous = std::min(static_cast<double>(params_.continuous_current_a), peak);
  if (std::abs(current_command_a_) > continuous)
    above_continuous_s_ += dt_s();
  else
    above_continuous_s_ = 0.0;
  return above_continuous_s_ > kPeakCurrentTime_s ? continuous : peak;
}

void Axis::close_loop() {
  const double dt = dt_s();
  const double limit_a = current_limit_a();
  const LoopInputs in{ref_.position_counts,
                      ref_.velocity_counts_per_s,
                      ref_.accel_counts_per_s2,
                      motor_state_.position_counts,
                      motor_state_.velocity_counts_per_s,
                      accel_per_amp_counts_per_s2_};
  switch (params_.unit_mode) {
    case 1:
      current_command_a_ = std::clamp(static_cast<double>(torque_command_a_), -limit_a, limit_a);
      break;
    case 2:
      velocity_command_counts_per_s_ = ref_.velocity_counts_per_s;
      current_command_a_ =
          velocity_loop(params_.gains, loop_, velocity_command_counts_per_s_, in, limit_a, dt);
      break;
    default:
      velocity_command_counts_per_s_ = position_loop(params_.gains, loop_, in, dt);
      current_command_a_ =
          velocity_loop(params_.gains, loop_, velocity_command_counts_per_s_, in, limit_a, dt);
      break;
  }
  const double voltage = current_loop(params_.gains, loop_, current_command_a_,
                                      motor_state_.current_a, motor_.bus_voltage_v, dt);
  step_motor(motor_, motor_step(), motor_state_, voltage);
  if (end_stops_.placed) meet_end_stops();
}

inline void Axis::check_faults() {
  const double position_error = ref_.position_counts - motor_state_.position_counts;
  const double velocity_error = velocity_command_counts_per_s_ - motor_state_.velocity_counts_per_s;
  const double v = motor_state_.velocity_counts_per_s;
  const double user_position = motor_state_.position_counts + offset_counts_;
  if (params_.unit_mode == 5 && std::abs(position_error) > params_.max_position_error_counts)
    latch_fault(kFaultFollowingError);
  else if (params_.unit_mode != 1 &&
           std::abs(velocity_error) > params_.max_velocity_error_counts_per_s)
    latch_fault(kFaultVelocityError);
  else if (v > params_.speed_fault_high_counts_per_s || v < params_.speed_fault_low_counts_per_s)
    latch_fault(kFaultSpeedLimit);
  else if (params_.unit_mode == 5 && !modulo_active() &&
           (user_position > params_.position_fault_high_counts ||
            user_position < params_.position_fault_low_counts))
    latch_fault(kFaultPositionLimit);
  else if (std::abs(motor_state_.current_a) > 1.5 * params_.peak_current_a + 0.1)
    latch_fault(kFaultOvercurrent);
}

// How long the position has been within TR[1] of a reached point-to-point target (MS=0).
inline void Axis::track_target_window() {
  if (!servo_ready_ || moving_ || !has_target_ || params_.unit_mode != 5) {
    in_window_us_ = -1;
    return;
  }
  const double error = std::abs(ref_.position_counts - motor_state_.position_counts);
  if (error > params_.target_radius_counts)
    in_window_us_ = -1;
  else
    in_window_us_ = in_window_us_ < 0 ? 0 : in_window_us_ + period_us();
}

// ---------------------------------------------------------------- homing

void Axis::arm_homing(bool arm) {
  if (arm)
    homing_.arm();
  else
    homing_.disarm();
}

uint32_t Axis::step_homing(double position_before_counts) {
  if (!homing_.armed()) {
    // Without an armed process a main-home input's activation is itself the home event, as the
    // Gold manual's AUTO_HM (2.14.9) has it; nothing is captured or set.
    return home_input_rose_ ? static_cast<uint32_t>(kEventHome) : 0u;
  }
  HomingCycle cycle;
  cycle.switch_edge = home_switch_edge();
  cycle.position_counts = motor_state_.position_counts;
  const HomeTrigger trigger = homing_settings_.trigger;
  if (trigger == HomeTrigger::kIndex || trigger == HomeTrigger::kHomeInputThenIndex) {
    cycle.index_at_counts = index_crossed(index_offset_counts_, params_.counts_per_revolution(),
                                          position_before_counts, motor_state_.position_counts);
  }
  const std::optional<double> at = homing_.step(trigger, cycle);
  if (!at) return 0;
  home_event(*at);
  return kEventHome;
}

namespace {
// The input function whose edge a homing switch waits for (kInput names an input instead).
InputFunction switch_function(HomeSwitch s) {
  switch (s) {
    case HomeSwitch::kForwardLimit:
      return InputFunction::kForwardLimit;
    case HomeSwitch::kReverseLimit:
      return InputFunction::kReverseLimit;
    default:
      return InputFunction::kHome;
  }
}
}  // namespace

bool Axis::home_switch_edge() const {
  const HomingSettings& h = homing_settings_;
  const uint32_t edges = h.on_release ? inputs_fell_ : inputs_rose_;
  if (edges == 0) return false;
  if (h.home_switch == HomeSwitch::kInput)
    return h.input >= 1 && h.input <= kInputCount && (edges & (1u << (h.input - 1))) != 0;
  const InputFunction wanted = switch_function(h.home_switch);
  for (int n = 1; n <= kInputCount; ++n) {
    const bool edge = (edges & (1u << (n - 1))) != 0;
    if (edge && input_function(params_.input_logic[n - 1]) == wanted) return true;
  }
  return false;
}

void Axis::home_event(double at_counts) {
  ++home_events_;
  home_capture_ = internal_to_user(at_counts);
  const HomingSettings& h = homing_settings_;
  switch (h.setting) {
    case HomePositionSetting::kAbsolute:
      set_position(h.home_value_counts);
      break;
    case HomePositionSetting::kRelative:
      // The captured point becomes the home value; the distance travelled since it is kept.
      offset_counts_ += static_cast<double>(h.home_value_counts) - home_capture_;
      break;
    case HomePositionSetting::kKeep:
      break;
  }
  switch (h.action) {
    case HomeAction::kStop:
      stop_with(params_.stop_decel_counts_per_s2);
      break;
    case HomeAction::kSetOutput:
      set_output(h.output, true);
      break;
    case HomeAction::kContinue:
      break;
  }
}

const MotorStep& Axis::motor_step() {
  if (motor_step_.dt_s != dt_s()) motor_step_ = motor_step_constants(motor_, dt_s());
  return motor_step_;
}

// Each from the feedback, not one copied from the other: a copy reads back the stores just made,
// wider than they were, and waits for them (most of an idle cycle's time in this function).
void Axis::hold_reference_at_feedback() {
  const ProfileSample at_rest{motor_state_.position_counts, 0.0, 0.0};
  raw_ = at_rest;
  ref_ = at_rest;
}

uint32_t Axis::step() {
  uint32_t events = pending_events_;
  pending_events_ = 0;
  ++cycles_;
  time_us_ += period_us();
  if (any_switch_) follow_position_switches();
  home_input_rose_ = false;
  inputs_rose_ = inputs_fell_ = 0;
  if (inputs_changed_ || inhibit_active_) events |= scan_inputs();
  const double position_before = motor_state_.position_counts;

  if (motor_on_ && !servo_ready_) {
    enable_elapsed_us_ += period_us();
    if (enable_elapsed_us_ >= kEnableDelay_us) {
      servo_ready_ = true;
      loop_ = LoopState{};
      hold_reference_at_feedback();
      smooth_position_.reset(1, raw_.position_counts);
      smooth_velocity_.reset(1, 0.0);
      smooth_accel_.reset(1, 0.0);
      if (!target_set_while_enabling_ && !moving_) {
        target_internal_ = raw_.position_counts;
        pa_counts_ = internal_to_user(target_internal_);
      }
    }
  }

  if (servo_ready_) {
    if (forward_limit_active_ || reverse_limit_active_ || hard_stop_active_) enforce_limits();
    advance_profile();
    close_loop();
  } else {
    // The bridge is open: no current flows and the load coasts; the reference follows the
    // feedback so that PE stays 0 and enabling does not jump. A load at rest stays there (no
    // current, no speed, no friction: step_motor would leave it exactly as it is).
    if (motor_state_.velocity_counts_per_s != 0.0 || motor_state_.current_a != 0.0) {
      motor_state_.current_a = 0.0;
      const double back_emf_v = motor_.torque_constant_nm_per_a *
                                motor_state_.velocity_counts_per_s * motor_step().rad_per_count;
      step_motor(motor_, motor_step(), motor_state_, back_emf_v);
      motor_state_.current_a = 0.0;
      if (end_stops_.placed) meet_end_stops();
    }
    hold_reference_at_feedback();
  }

  if (servo_ready_) check_faults();
  track_target_window();
  if (homing_.armed() || home_input_rose_) events |= step_homing(position_before);
  events |= pending_events_;
  pending_events_ = 0;
  last_events_ = events;
  if (recorder_.active()) recorder_.on_cycle(*this);
  return events;
}

}  // namespace uprog::drive
