// The SF smoothing filter: a moving average of the reference position over SF milliseconds.
// Averaging a trapezoid over a window T turns each acceleration step into a ramp of length T,
// so the jerk is bounded by max(AC, DC) / T, and a move still ends exactly at its target.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace uprog::drive {

class MovingAverage {
 public:
  // A window of `length` samples (1 = no smoothing); every slot starts at `initial`.
  void reset(uint32_t length, double initial);
  // Pushes a sample and returns the average of the last `length` samples. Without a window
  // (SF=0, the usual case, three pushes every servo cycle) the sample is its own average.
  double push(double sample) {
    if (window_.size() != 1) return push_windowed(sample);
    window_[0] = sample;
    sum_ = sample;
    return sample;
  }
  // Moves every stored sample by `delta` (used when the position is redefined).
  void shift(double delta);
  bool settled() const;  // all samples in the window are equal
  uint32_t length() const { return static_cast<uint32_t>(window_.size()); }

 private:
  double push_windowed(double sample);

  std::vector<double> window_{0.0};
  double sum_ = 0.0;
  std::size_t next_ = 0;
  uint32_t equal_run_ = 0;  // how many consecutive pushes repeated the previous sample
};

}  // namespace uprog::drive
