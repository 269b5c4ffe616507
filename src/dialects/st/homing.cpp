// MH's searching types on the simulated S300 (firmware.h; docs/dialects/st.md, "Homing to a
// switch or a stop"): the search at VREF in DREF's direction for the reference switch (NREF 1,
// 3), a hardware limit switch (NREF 2, 4) or a mechanical stop (NREF 7, 9: the following error
// beyond PEMAX/2), the zero mark after it (NREF 1; NREF 2 and 7 back, away from the limit or
// stop), and the move back to the reference point found, which then reads ROFFS. The inputs
// are those IN1MODE…IN4MODE gave a function at the last boot (2 PSTOP, 3 NSTOP, 12 reference).
#include "drive/homing.h"

#include <algorithm>
#include <cmath>

#include "dialects/st/firmware.h"
#include "drive/axis.h"

namespace uprog::st {
namespace {

constexpr int32_t kModePositiveStop = 2;  // PSTOP: low blocks the positive direction
constexpr int32_t kModeNegativeStop = 3;  // NSTOP: low blocks the negative direction
constexpr double kSearchCounts = 1e9;     // how far a search may run before it gives up

}  // namespace

bool Firmware::homing_input_active() const {
  const bool high = axis_->input_level(switch_homing_.input);
  return switch_homing_.criterion == SwitchHoming::kLimitSwitch ? !high : high;
}

// The switch's active level, or a stop: the reference's REFPOS for NREF 7, "a stop (PE > PEMAX
// / 2)", the following error the motor builds against it.
bool Firmware::homing_criterion_met() const {
  if (switch_homing_.criterion != SwitchHoming::kMechanicalStop) return homing_input_active();
  const double following = axis_->reference_position_exact() - axis_->motor_state().position_counts;
  return std::fabs(following) > axis_->parameters().max_position_error_counts / 2.0;
}

void Firmware::head_for(double motor_counts) {
  const double motor = axis_->motor_state().position_counts;
  axis_->set_absolute_target_exact(axis_->position_exact() + (motor_counts - motor));
  axis_->begin();
}

void Firmware::end_homing() {
  switch_homing_.phase = SwitchHoming::kIdle;
  homing_ = false;
}

// NREF 1 and 3 need an input configured as the reference switch (12), NREF 2 and 4 the limit
// switch in DREF's direction (NSTOP 3 for 0, PSTOP 2 for 1): the reference's "NREF" page. NREF
// 7 and 9 need PEMAX, whose half is their criterion. The reference's DREF 2 (the shorter way to
// a zero mark) has no meaning for a search: refused.
int32_t Firmware::start_switch_homing(int32_t nref) {
  const int32_t dref = values_.at("DREF");
  if (dref > 1) return kErrRange;
  SwitchHoming h;
  h.criterion = nref == 1 || nref == 3   ? SwitchHoming::kReferenceSwitch
                : nref == 2 || nref == 4 ? SwitchHoming::kLimitSwitch
                                         : SwitchHoming::kMechanicalStop;
  h.direction = dref == 0 ? -1.0 : 1.0;
  h.zero_mark = nref == 1 || nref == 2 || nref == 7;
  h.mark_behind = nref == 2 || nref == 7;
  if (h.criterion == SwitchHoming::kMechanicalStop) {
    if (values_.at("PEMAX") == 0) return kErrRange;
  } else {
    const int32_t wanted = h.criterion == SwitchHoming::kReferenceSwitch ? kModeReference
                           : dref == 0                                   ? kModeNegativeStop
                                                                         : kModePositiveStop;
    const auto it = std::find(input_modes_.begin(), input_modes_.end(), wanted);
    if (it == input_modes_.end()) return kErrRange;
    h.input = static_cast<int>(it - input_modes_.begin()) + 1;
  }
  if (!axis_->servo_ready()) return kErrNeedsEnabled;
  apply_limits();
  drive::Parameters& p = axis_->parameters();
  const double speed =
      std::min(std::fabs(counts_exact(values_.at("VREF"))), rpm_to_counts(values_.at("VLIM")));
  p.speed_counts_per_s = static_cast<int32_t>(std::max(1.0, std::round(speed)));
  const double ramp = ramp_counts_per_s2(values_.at("ACC"));
  p.accel_counts_per_s2 = p.decel_counts_per_s2 =
      static_cast<int32_t>(std::clamp(ramp, 1.0, 2147483647.0));
  next_pending_ = false;
  homing_ = false;
  switch_homing_ = h;
  const double motor = axis_->motor_state().position_counts;
  // Standing on the switch, the drive first leaves it the other way (the reference's DREF:
  // only DREF 4 and 5 make "no positive movement on reference switch or limit switch").
  const bool on_switch = h.criterion != SwitchHoming::kMechanicalStop && homing_input_active();
  switch_homing_.phase = on_switch ? SwitchHoming::kLeave : SwitchHoming::kSearch;
  head_for(motor + (on_switch ? -1.0 : 1.0) * h.direction * kSearchCounts);
  return 0;
}

// The criterion seen at `motor`: REFPOS takes it. Without a zero mark the axis stops and goes
// back to it; NREF 1 goes on to the first zero mark; NREF 2 and 7, which cannot go on, turn back
// (NREF 2 to the first mark after it has left the limit switch).
void Firmware::found_criterion(double motor) {
  SwitchHoming& h = switch_homing_;
  refpos_motor_ = h.capture = h.last_motor = motor;
  if (!h.zero_mark) {
    h.phase = SwitchHoming::kStop;
    axis_->stop();
  } else if (!h.mark_behind) {
    h.phase = SwitchHoming::kMark;
  } else {
    h.phase = h.criterion == SwitchHoming::kLimitSwitch ? SwitchHoming::kBack : SwitchHoming::kMark;
    head_for(motor - h.direction * kSearchCounts);
  }
}

// One axis step of the search. The criterion is where the drive sees it (the reference's
// REFPOS: "the rising edge of the reference switch" for 1 and 3, "the falling edge" of the limit
// switch for 2 and 4, "a stop (PE > PEMAX / 2)" for 7). The axis then stops and moves back to
// the point found, which becomes the reference point (the sercos manual's IDN 147: stop "on
// home position").
void Firmware::step_switch_homing() {
  SwitchHoming& h = switch_homing_;
  if (h.phase == SwitchHoming::kIdle) return;
  if (!axis_->motor_on()) return end_homing();
  const double motor = axis_->motor_state().position_counts;
  const bool moving = axis_->profiler_moving();
  switch (h.phase) {
    case SwitchHoming::kLeave:
      if (!homing_input_active()) {
        h.phase = SwitchHoming::kSearch;
        head_for(motor + h.direction * kSearchCounts);
      } else if (!moving) {
        end_homing();  // the switch never ended
      }
      return;
    case SwitchHoming::kSearch:
      if (homing_criterion_met())
        found_criterion(motor);
      else if (!moving)
        end_homing();  // nothing within the search's reach
      return;
    case SwitchHoming::kBack:
      if (!homing_input_active()) {
        h.phase = SwitchHoming::kMark;
        h.last_motor = motor;
      } else if (!moving) {
        end_homing();
      }
      return;
    case SwitchHoming::kMark:
      if (auto mark = drive::index_crossed(axis_->index_offset(),
                                           axis_->parameters().counts_per_revolution(),
                                           h.last_motor, motor)) {
        h.capture = *mark;
        h.phase = SwitchHoming::kStop;
        axis_->stop();
      } else if (!moving) {
        end_homing();
      }
      h.last_motor = motor;
      return;
    case SwitchHoming::kStop:
      if (!moving) {
        h.phase = SwitchHoming::kReturn;
        head_for(h.capture);
      }
      return;
    case SwitchHoming::kReturn:
      if (!moving) {
        set_reference(h.capture);
        end_homing();
      }
      return;
    case SwitchHoming::kIdle:
      return;
  }
}

}  // namespace uprog::st
