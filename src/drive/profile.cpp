// Trapezoidal motion planning: closed-form segment durations for moves, jogs and stops.
#include "drive/profile.h"

#include <algorithm>
#include <cmath>

namespace uprog::drive {
namespace {

// The profile's start state must be set before its first segment is pushed.
void push(Profile& p, double duration_s, double accel) {
  if (duration_s <= 0.0) return;
  double pos = p.start_position_counts;
  double vel = p.start_velocity_counts_per_s;
  if (p.segment_count > 0) {
    const Segment& last = p.segments[static_cast<size_t>(p.segment_count - 1)];
    pos = p.end_position_counts;
    vel = last.start_velocity_counts_per_s + last.accel_counts_per_s2 * last.duration_s;
  }
  p.segments[static_cast<size_t>(p.segment_count++)] = {duration_s, accel, pos, vel};
  p.end_position_counts = pos + (vel * duration_s + 0.5 * accel * duration_s * duration_s);
}

double sign(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

// Appends a move from (velocity u0 >= 0 along direction dir) over a distance >= the
// stopping distance u0^2/(2 dec), ending at rest.
void append_forward_move(Profile& p, double dir, double u0, double distance,
                         const MotionLimits& lim) {
  const double vmax = lim.speed_counts_per_s;
  const double acc = lim.accel_counts_per_s2;
  const double dec = lim.decel_counts_per_s2;
  if (u0 > vmax) {
    // Slow down to the speed limit first, cruise, then stop.
    const double slow_distance = (u0 * u0 - vmax * vmax) / (2.0 * dec);
    const double stop_distance = vmax * vmax / (2.0 * dec);
    push(p, (u0 - vmax) / dec, -dir * dec);
    push(p, (distance - slow_distance - stop_distance) / vmax, 0.0);
    push(p, vmax / dec, -dir * dec);
    return;
  }
  // Peak speed of a triangle: distance = (vp^2 - u0^2)/(2 acc) + vp^2/(2 dec).
  const double peak_sq =
      (distance + u0 * u0 / (2.0 * acc)) / (1.0 / (2.0 * acc) + 1.0 / (2.0 * dec));
  double peak = std::sqrt(std::max(peak_sq, 0.0));
  double cruise_s = 0.0;
  if (peak > vmax) {
    peak = vmax;
    const double ramps = (vmax * vmax - u0 * u0) / (2.0 * acc) + vmax * vmax / (2.0 * dec);
    cruise_s = (distance - ramps) / vmax;
  }
  peak = std::max(peak, u0);
  push(p, (peak - u0) / acc, dir * acc);
  push(p, cruise_s, 0.0);
  push(p, peak / dec, -dir * dec);
}

}  // namespace

double Profile::duration_s() const {
  double t = 0.0;
  for (int i = 0; i < segment_count; ++i) t += segments[static_cast<size_t>(i)].duration_s;
  return t;
}

ProfileSample Profile::final_state() const {
  if (has_target) return {target_counts, 0.0, 0.0};
  return {segment_count > 0 ? end_position_counts : start_position_counts,
          end_velocity_counts_per_s, 0.0};
}

Profile plan_move(double start_position_counts, double start_velocity_counts_per_s,
                  double target_counts, const MotionLimits& limits) {
  Profile p;
  p.start_position_counts = start_position_counts;
  p.start_velocity_counts_per_s = start_velocity_counts_per_s;
  p.has_target = true;
  p.target_counts = target_counts;
  const double v0 = start_velocity_counts_per_s;
  const double dec = limits.decel_counts_per_s2;
  const double distance = target_counts - start_position_counts;
  const double stop_distance = v0 * v0 / (2.0 * dec);
  const double dir = sign(distance);
  if (v0 == 0.0 || (sign(v0) == dir && std::abs(distance) >= stop_distance)) {
    if (dir != 0.0) append_forward_move(p, dir, std::abs(v0), std::abs(distance), limits);
    return p;
  }
  // Moving away from the target, or too fast to stop before it: brake, then come back.
  push(p, std::abs(v0) / dec, -sign(v0) * dec);
  const double stopped_at = start_position_counts + sign(v0) * stop_distance;
  const double rest = target_counts - stopped_at;
  if (rest != 0.0) append_forward_move(p, sign(rest), 0.0, std::abs(rest), limits);
  return p;
}

Profile plan_jog(double start_position_counts, double start_velocity_counts_per_s,
                 double jog_velocity_counts_per_s, const MotionLimits& limits) {
  Profile p;
  p.start_position_counts = start_position_counts;
  p.start_velocity_counts_per_s = start_velocity_counts_per_s;
  const double v0 = start_velocity_counts_per_s;
  const double vj = jog_velocity_counts_per_s;
  const double acc = limits.accel_counts_per_s2;
  const double dec = limits.decel_counts_per_s2;
  p.end_velocity_counts_per_s = vj;
  if (v0 * vj >= 0.0 && std::abs(vj) >= std::abs(v0)) {
    push(p, std::abs(vj - v0) / acc, sign(vj - v0) * acc);
  } else if (v0 * vj > 0.0) {
    push(p, std::abs(vj - v0) / dec, sign(vj - v0) * dec);
  } else {
    push(p, std::abs(v0) / dec, -sign(v0) * dec);
    push(p, std::abs(vj) / acc, sign(vj) * acc);
  }
  return p;
}

Profile plan_stop(double start_position_counts, double start_velocity_counts_per_s,
                  double decel_counts_per_s2) {
  Profile p;
  p.start_position_counts = start_position_counts;
  p.start_velocity_counts_per_s = start_velocity_counts_per_s;
  push(p, std::abs(start_velocity_counts_per_s) / decel_counts_per_s2,
       -sign(start_velocity_counts_per_s) * decel_counts_per_s2);
  return p;
}

}  // namespace uprog::drive
