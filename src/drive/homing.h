// Homing and capture, as every vendor's drive does it: an armed homing process waits for its
// event (at once, a switch's edge, the encoder's index pulse, or the first index after the
// switch's edge), captures the position there, and then sets the position counter and stops or
// continues the motion. The axis feeds it one servo cycle at a time (axis.cpp).
#pragma once
#include <cstdint>
#include <optional>

namespace uprog::drive {

// What ends the homing process (Gold HM[3]; the vendor's numbering is the dialect's).
enum class HomeTrigger : uint8_t {
  kImmediate,           // the next servo cycle
  kHomeInput,           // the home switch's edge (HomingSettings::home_switch, on_release)
  kIndex,               // the encoder's index pulse is crossed
  kHomeInputThenIndex,  // the first index pulse after the home switch's edge
};

// The switch whose edge kHomeInput and kHomeInputThenIndex wait for.
enum class HomeSwitch : uint8_t {
  kMainHome,      // any input whose function is main home (IL 16/17)
  kForwardLimit,  // any input whose function is the forward limit
  kReverseLimit,  // any input whose function is the reverse limit
  kInput,         // input HomingSettings::input, whatever its function
};

// What the motion does at the home event (Gold HM[4]).
enum class HomeAction : uint8_t {
  kStop = 0,       // the motion stops with SD
  kSetOutput = 1,  // the motion continues; the output `HomingSettings::output` is set
  kContinue = 2,   // the motion continues
};
constexpr int32_t kHomeActionMax = 2;

// What the position counter does at the home event (Gold HM[5]).
enum class HomePositionSetting : uint8_t {
  kAbsolute = 0,  // the position counter becomes the home value
  kRelative = 1,  // the captured position becomes the home value; the distance since is kept
  kKeep = 2,      // the counter is left alone (capture only)
};
constexpr int32_t kHomePositionSettingMax = 2;

struct HomingSettings {
  HomeTrigger trigger = HomeTrigger::kImmediate;
  HomeSwitch home_switch = HomeSwitch::kMainHome;
  int32_t input = 1;        // kInput: the input, 1..kInputCount
  bool on_release = false;  // the switch's edge: false when it becomes active, true inactive
  HomeAction action = HomeAction::kStop;
  HomePositionSetting setting = HomePositionSetting::kAbsolute;
  int32_t home_value_counts = 0;  // Gold HM[2]
  int32_t output = 0;             // the output kSetOutput sets, 1..kOutputCount; 0 sets none

  bool operator==(const HomingSettings&) const = default;
};

// What one servo cycle saw.
struct HomingCycle {
  bool switch_edge = false;               // the home switch's edge came this cycle
  std::optional<double> index_at_counts;  // the index pulse crossed, where (motor counts)
  double position_counts = 0.0;           // the motor's position at the end of the cycle
};

class Homing {
 public:
  void arm() {
    armed_ = true;
    home_input_seen_ = false;
  }
  void disarm() { armed_ = false; }
  bool armed() const { return armed_; }

  // The position of the home event if it happened this cycle (the process then disarms).
  std::optional<double> step(HomeTrigger trigger, const HomingCycle& cycle);

 private:
  bool armed_ = false;
  bool home_input_seen_ = false;  // kHomeInputThenIndex: the edge came, the index is awaited
};

// The index position (offset + k * period) a move from `from` to `to` crossed, if any; the first
// one when it crossed several. `to` itself counts, `from` does not, so a pulse is met once
// however the cycles fall.
std::optional<double> index_crossed(double offset_counts, double period_counts, double from_counts,
                                    double to_counts);

}  // namespace uprog::drive
