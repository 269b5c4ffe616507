// Moving average with a running sum that is recomputed once per window turn, so rounding
// cannot accumulate over a long run.
#include "drive/smoothing.h"

#include <algorithm>

namespace uprog::drive {

void MovingAverage::reset(uint32_t length, double initial) {
  window_.assign(std::max<uint32_t>(length, 1u), initial);
  sum_ = initial * static_cast<double>(window_.size());
  next_ = 0;
  equal_run_ = static_cast<uint32_t>(window_.size());
}

double MovingAverage::push_windowed(double sample) {
  const size_t n = window_.size();
  const size_t previous = next_ == 0 ? n - 1 : next_ - 1;
  equal_run_ = window_[previous] == sample ? equal_run_ + 1 : 0;
  sum_ += sample - window_[next_];
  window_[next_] = sample;
  next_ = next_ + 1 == n ? 0 : next_ + 1;
  if (next_ == 0) {
    sum_ = 0.0;
    for (double v : window_) sum_ += v;
  }
  // When the window holds one value, return it exactly rather than sum / n.
  if (settled()) return sample;
  return sum_ / static_cast<double>(window_.size());
}

void MovingAverage::shift(double delta) {
  for (double& v : window_) v += delta;
  sum_ = 0.0;
  for (double v : window_) sum_ += v;
}

bool MovingAverage::settled() const { return equal_run_ + 1 >= window_.size(); }

}  // namespace uprog::drive
