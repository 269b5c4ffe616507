// Position-time (PT) tabulated motion as a pure function: a table of positions, one picked every
// `cycles_per_point` servo cycles from a start index, linearly interpolated between points,
// cyclic between `first` and `last` or ending at `last`.
#pragma once
#include <array>
#include <cstdint>

namespace uprog::drive {

constexpr int kPtPoints = 1024;  // QP[1..1024]

struct PtTable {
  std::array<int32_t, kPtPoints> positions{};  // index 0 is QP[1]
  int32_t first = 1;                           // MP[1]
  int32_t last = 1;                            // MP[2]
  bool cyclic = false;                         // MP[3]
  int32_t cycles_per_point = 1;                // MP[4]

  bool operator==(const PtTable&) const = default;
};

struct PtSample {
  double position_counts;
  double velocity_counts_per_s;
  int32_t index;  // the point the motion is leaving (PT reads it)
  bool ended;     // a non-cyclic motion reached `last`: the position is QP[last]
};

// True when a motion can start at `start`: first <= start <= last, all within the table, and a
// positive cycles_per_point.
bool pt_can_start(const PtTable& table, int32_t start);

// The reference `cycles` servo cycles after a motion started at `start` (pt_can_start holds).
PtSample sample_pt(const PtTable& table, int32_t start, uint64_t cycles, double period_s);

}  // namespace uprog::drive
