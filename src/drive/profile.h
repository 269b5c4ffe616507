// Motion profiles as pure functions of their inputs (in the manner of Ruckig): a plan is a start
// state and a short list of constant-acceleration segments; sampling it at a time is exact.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>

namespace uprog::drive {

struct MotionLimits {
  double speed_counts_per_s;   // SP, > 0
  double accel_counts_per_s2;  // AC, > 0 (used to speed up)
  double decel_counts_per_s2;  // DC, > 0 (used to slow down)
};

struct Segment {
  double duration_s;
  double accel_counts_per_s2;
  // The state the segment starts from, kept when it is planned so that sampling does not add up
  // the segments before it every servo cycle.
  double start_position_counts = 0.0;
  double start_velocity_counts_per_s = 0.0;
};

// Reference state at one instant.
struct ProfileSample {
  double position_counts;
  double velocity_counts_per_s;
  double accel_counts_per_s2;
};

// After its last segment a profile continues with constant velocity: zero for a move or a stop,
// the jog velocity for a jog.
struct Profile {
  static constexpr int kMaxSegments = 6;
  double start_position_counts = 0.0;
  double start_velocity_counts_per_s = 0.0;
  std::array<Segment, kMaxSegments> segments{};
  int segment_count = 0;
  double end_position_counts = 0.0;        // where the last segment ends (with segments only)
  double end_velocity_counts_per_s = 0.0;  // exact, so a move ends at rest without rounding
  bool has_target = false;                 // a move: from its end on, the position is exactly
  double target_counts = 0.0;              // the target, free of the segments' rounding

  double duration_s() const;
  // The state the profile reaches at its end (and keeps, moving on at the final velocity).
  ProfileSample final_state() const;
};

// A point-to-point move from (position, velocity) to rest at target. If the start velocity
// would carry the axis past the target, the plan brakes with DC first and comes back.
Profile plan_move(double start_position_counts, double start_velocity_counts_per_s,
                  double target_counts, const MotionLimits& limits);

// An endless jog: ramp from the start velocity to jog velocity (AC to speed up, DC to slow down).
Profile plan_jog(double start_position_counts, double start_velocity_counts_per_s,
                 double jog_velocity_counts_per_s, const MotionLimits& limits);

// Decelerate to standstill with the given deceleration.
Profile plan_stop(double start_position_counts, double start_velocity_counts_per_s,
                  double decel_counts_per_s2);

// The reference at t_s seconds after the profile's start (t_s < 0 gives the start state).
// Inline: the axis samples it every servo cycle, and a returned struct would pass through memory
// (its three stores read back by wider loads, which wait for them).
inline ProfileSample sample(const Profile& profile, double t_s) {
  // The time left is reduced segment by segment, as final_state() adds them up.
  double remaining = std::max(t_s, 0.0);
  for (int i = 0; i < profile.segment_count; ++i) {
    const Segment& seg = profile.segments[static_cast<size_t>(i)];
    if (remaining < seg.duration_s) {
      const double vel = seg.start_velocity_counts_per_s;
      return {seg.start_position_counts +
                  (vel * remaining + 0.5 * seg.accel_counts_per_s2 * remaining * remaining),
              vel + seg.accel_counts_per_s2 * remaining, seg.accel_counts_per_s2};
    }
    remaining -= seg.duration_s;
  }
  const ProfileSample end = profile.final_state();
  if (profile.has_target) return end;
  return {end.position_counts + end.velocity_counts_per_s * remaining, end.velocity_counts_per_s,
          0.0};
}

}  // namespace uprog::drive
