// PT sampling: which segment a cycle count falls in, and where in it.
#include "drive/pt_table.h"

#include <cstddef>

namespace uprog::drive {

bool pt_can_start(const PtTable& t, int32_t start) {
  return t.first >= 1 && t.last <= kPtPoints && t.first <= t.last && start >= t.first &&
         start <= t.last && t.cycles_per_point >= 1;
}

PtSample sample_pt(const PtTable& t, int32_t start, uint64_t cycles, double period_s) {
  const uint64_t per = static_cast<uint64_t>(t.cycles_per_point);
  const uint64_t segment = cycles / per;
  const double fraction = static_cast<double>(cycles % per) / static_cast<double>(per);
  const auto at = [&](int64_t index) {
    return static_cast<double>(t.positions[static_cast<std::size_t>(index - 1)]);
  };
  const int64_t first = t.first, last = t.last;
  int64_t index = start + static_cast<int64_t>(segment);
  if (!t.cyclic) {
    if (index >= last) return {at(last), 0.0, static_cast<int32_t>(last), true};
  } else {
    // The points first..last repeat; the segment from last leads back to first.
    index = first + (index - first) % (last - first + 1);
  }
  const int64_t next = index == last ? first : index + 1;
  const double from = at(index), to = at(next);
  const double velocity = (to - from) / (static_cast<double>(per) * period_s);
  return {from + fraction * (to - from), velocity, static_cast<int32_t>(index), false};
}

}  // namespace uprog::drive
