// One simulated servo axis in virtual time: profile generator, cascaded loops, motor model,
// digital I/O, limits, faults and homing. `step()` advances one servo cycle (TS) and reports
// events. The axis knows physics and parameters, not languages: a dialect maps its commands
// onto it.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "drive/events.h"
#include "drive/homing.h"
#include "drive/motor_model.h"
#include "drive/parameters.h"
#include "drive/profile.h"
#include "drive/pt_table.h"
#include "drive/recorder.h"
#include "drive/rounding.h"
#include "drive/servo_loop.h"
#include "drive/smoothing.h"

namespace uprog::drive {

// Why the axis refused a request; a dialect maps these to its own error codes.
enum class Status : uint8_t {
  kOk,
  kOutOfRange,        // the value is outside what the parameter accepts
  kMotorOn,           // allowed only while the motor is off (UM, LD)
  kMotorOff,          // needs the motor on (BG)
  kFaultLatched,      // MO=1 while a fault's cause is still present
  kInhibitActive,     // MO=1 while an inhibit input is active
  kModeNotSupported,  // BG in UM=1, a PT motion outside UM=5; TC outside UM=1 has no effect
  kBadStartData,      // BG of a PT motion whose start index or table set-up is unusable
};

constexpr uint32_t kEnableDelay_us = 20000;  // MO=1 to SO=1
constexpr uint32_t kMinPeriod_us = 25;       // TS's range
constexpr uint32_t kMaxPeriod_us = 2000;
constexpr double kPeakCurrentTime_s = 3.0;  // PL[1] allowed this long, then CL[1]

// The status register (SR) as the Elmo reference lays it out (docs/dialects/gold.md, "SR").
// Bits 12 (program running) and 29 (error in the user program) belong to the program's host.
enum StatusRegisterBits : uint32_t {
  kSrDriveProblem = 1u << 0,  // a power-stage problem; its code is bits 1..3
  kSrPowerStageShift = 1,     // bits 1..3: the MF power-stage code
  kSrMotorOn = 1u << 4,
  kSrReferenceMode = 1u << 5,  // RM=1: an external reference selected
  kSrMotorFailure = 1u << 6,   // MF != 0
  kSrUnitModeShift = 8,        // bits 8..10 (Gold: bit 7 stays clear)
  kSrHoming = 1u << 11,        // a homing process is armed
  kSrProgramRunning = 1u << 12,
  kSrCurrentLimited = 1u << 13,  // the current is limited to CL[1] after PL[1]'s time
  kSrSafeTorqueOff1 = 1u << 14,  // Gold: STO input 1 permits enabling (no STO circuit:
  kSrSafeTorqueOff2 = 1u << 15,  // both always permit)
  kSrStoppedByLimit = 1u << 28,  // RLS, FLS, a stop input, or a VH[3]/VL[3] target limit
  kSrProgramError = 1u << 29,
};

class Axis {
 public:
  explicit Axis(const MotorModel& motor = MotorModel{});

  // One servo cycle; returns the events of this cycle (also kept for last_events()).
  uint32_t step();
  uint32_t last_events() const { return last_events_; }

  // --- parameters (SV/LD) ---
  // Direct access for the plain values (UI, UF, gains, limits, motion parameters).
  Parameters& parameters() { return params_; }
  const Parameters& parameters() const { return params_; }
  // LD: replaces every parameter; refused while the motor is on.
  Status load_parameters(const Parameters& params);
  Status set_unit_mode(int32_t mode);                // UM: 1, 2 or 5, motor off only
  Status set_input_logic(int n, int32_t logic);      // IL[n]
  Status set_period_us(int32_t period_us);           // TS, kMinPeriod_us..kMaxPeriod_us
  Status set_counts_per_revolution(int32_t counts);  // the encoder; spaces the index pulses

  // --- enable ---
  Status set_motor_on(bool on);  // MO
  bool motor_on() const { return motor_on_; }
  bool servo_ready() const { return servo_ready_; }  // SO

  // --- motion ---
  void set_absolute_target(int32_t target_counts);  // PA
  // A target between two counts, for a drive whose position units do not divide into counts
  // (its user units scaled by a gear ratio): the motor goes to the exact point (no modulo).
  void set_absolute_target_exact(double target_counts);
  void set_relative_move(int32_t distance_counts);       // PR
  void set_jog_velocity(int32_t velocity_counts_per_s);  // JV
  int32_t absolute_target() const { return pa_counts_; }
  int32_t relative_move() const { return pr_counts_; }
  void set_pt_start(int32_t index);    // PT: the next BG starts a PT motion there
  int32_t pt_index() const;            // the executing point, else the start
  PtTable& pt_table() { return pt_; }  // QP, MP
  const PtTable& pt_table() const { return pt_; }
  Status begin();  // BG (the recorder's begin-of-motion trigger sees it)
  // ST (and the motion side of KL): the profiler decelerates to a stop with SD; the motor stays
  // on and holds where it stops. Nothing happens at rest.
  void stop();
  // The same stop at `decel_counts_per_s2` instead of SD (a drive whose STOP has its own ramp).
  void stop_with(double decel_counts_per_s2);
  void set_torque_command(float current_a) { torque_command_a_ = current_a; }  // TC
  float torque_command() const { return torque_command_a_; }

  // --- feedback and status ---
  // Inline: a program polls them and the recorder samples them every servo cycle.
  int32_t position() const { return internal_to_user(motor_state_.position_counts); }  // PX
  // PX unrounded: a drive that scales counts into its own units rounds once, at the end.
  double position_exact() const { return motor_state_.position_counts + offset_counts_; }
  void set_position(int32_t position_counts);
  int32_t velocity() const {
    return static_cast<int32_t>(round_half_away(motor_state_.velocity_counts_per_s));
  }                                 // VX
  int32_t position_error() const {  // PE
    return static_cast<int32_t>(
        round_half_away(ref_.position_counts - motor_state_.position_counts));
  }
  int32_t reference_velocity() const {
    return static_cast<int32_t>(round_half_away(ref_.velocity_counts_per_s));
  }                                                                                      // DV[2]
  int32_t reference_position() const { return internal_to_user(ref_.position_counts); }  // DV[3]
  float current_command() const { return static_cast<float>(current_command_a_); }       // DV[1]
  int32_t motion_status() const;  // MS: 0 settled, 1 stationary, 2 moving, 3 motor off
  // The kind of motion BG last began while the motor is on (Gold OV[2]).
  enum class MotionKind : uint8_t { kNone, kPointToPoint, kJog, kPt };
  MotionKind motion_kind() const { return motor_on_ ? motion_kind_ : MotionKind::kNone; }
  uint32_t status_register() const;  // SR, without the program's bits 12 and 29
  // Nothing more will happen by itself: the motor is off, or no profiler runs and a reached
  // target has settled (MS=0). What the old "MS is 0 or 3" meant (tools/uprog/cmd_run.cpp).
  bool at_rest() const {
    return !servo_ready_ || (!moving_ && (!has_target_ || motion_status() == 0));
  }
  uint32_t motor_fault() const { return fault_bits_; }  // MF
  bool profiler_moving() const { return moving_; }

  // --- digital I/O ---
  void set_input_level(int n, bool high);  // the electrical level of input n (1..6)
  bool input_level(int n) const;
  uint32_t input_level_bits() const { return input_levels_; }  // bit n-1 for input n
  bool input_active(int n) const;  // the logical state of input n (its IL polarity)
  uint32_t input_port() const;     // IP (inputs.h, InputPortBits)
  void set_output_port(uint32_t bits) { outputs_ = bits & 0xFu; }  // OP
  uint32_t output_port() const { return outputs_; }
  void set_output(int n, bool on);  // OB[n]
  bool output(int n) const { return ((outputs_ >> (n - 1)) & 1u) != 0; }

  // --- homing and capture (homing.h) ---
  HomingSettings& homing_settings() { return homing_settings_; }
  const HomingSettings& homing_settings() const { return homing_settings_; }
  void arm_homing(bool arm);  // HM[1]=1 arms, HM[1]=0 disarms
  bool homing_armed() const { return homing_.armed(); }
  int32_t home_capture() const { return home_capture_; }  // PX at the last home event
  uint32_t home_event_count() const { return home_events_; }

  // --- the world a scenario places (positions are the motor's, in counts, whatever PX says) ---
  // The encoder's index pulse: once per revolution (CA[18] counts) at offset + k * CA[18].
  void place_index_pulse(double offset_counts) { index_offset_counts_ = offset_counts; }
  double index_offset() const { return index_offset_counts_; }
  // Input n's level follows the motor: high while the position lies in [from, to]. A switch
  // placed on an input replaces its level; set_input_level() on it removes the switch.
  void place_position_switch(int n, double from_counts, double to_counts);
  void remove_position_switch(int n);
  struct PositionSwitch {
    bool placed = false;
    double from_counts = 0.0, to_counts = 0.0;
  };
  // Mechanical end stops: the load cannot leave [low, high] (motor counts). A motor driven into
  // one stands there (its speed toward it is lost) while the reference runs on, so the
  // following error grows against it. Placed again, they replace the last ones.
  struct EndStops {
    bool placed = false;
    double low_counts = 0.0, high_counts = 0.0;
  };
  void place_end_stops(double low_counts, double high_counts);
  // All of the above: the world outside the drive, which a reset does not change, so that the
  // controller carries it to the fresh axes.
  struct World {
    uint32_t input_levels = 0;  // bit n-1 for input n
    std::array<PositionSwitch, kInputCount> switches{};
    double index_offset_counts = 0.0;
    EndStops end_stops{};
  };
  World world() const { return {input_levels_, switches_, index_offset_counts_, end_stops_}; }
  // The world as a drive finds it at power-up: the inputs start at its levels (no edge).
  void place_world(const World& world);

  // --- auxiliary feedback: the simulated drive has no second encoder; PY is a plain counter ---
  int32_t aux_position() const { return aux_position_counts_; }
  void set_aux_position(int32_t counts) { aux_position_counts_ = counts; }

  // --- faults ---
  // Latches the named fault (faults.h); with `persistent` its cause stays until
  // clear_fault_cause, and MO=1 is refused meanwhile. False when the name is unknown.
  bool inject_fault(std::string_view name, bool persistent = false);
  void clear_fault_cause(std::string_view name);
  // A fault reset (a drive's clear-fault command): MF keeps only the faults whose cause is still
  // present; the motor stays as it is.
  void clear_faults();
  // The power-stage codes latched since the faults were last cleared, bit n for code n: MF
  // holds one code, and a second power-stage fault would hide the first.
  uint32_t latched_power_stage_codes() const { return power_stage_codes_; }

  // --- time ---
  uint32_t time_us() const { return time_us_; }  // TM, wraps at 2^32
  void set_time_us(uint32_t t) { time_us_ = t; }
  uint32_t period_us() const { return static_cast<uint32_t>(params_.servo_period_us); }
  uint64_t cycle_count() const { return cycles_; }

  // --- the recorder (recorder.h): it samples after each step while active ---
  Recorder& recorder() { return recorder_; }
  const Recorder& recorder() const { return recorder_; }

  const MotorModel& motor_model() const { return motor_; }
  const MotorState& motor_state() const { return motor_state_; }
  double reference_position_exact() const { return ref_.position_counts; }

 private:
  double dt_s() const { return params_.servo_period_us * 1e-6; }
  double user_to_internal(int64_t user) const;
  // A 32-bit position counter wraps, as a real drive's does: modulo 2^32 of the rounded count.
  int32_t internal_to_user(double internal) const {
    const double exact = internal + offset_counts_;
    if (!modulo_active() && std::fabs(exact) < kExactRoundingLimit)
      return static_cast<int32_t>(static_cast<uint32_t>(round_half_away(exact)));
    return internal_to_user_slow(exact);
  }
  int32_t internal_to_user_slow(double exact) const;  // modulo counts, or beyond 2^62
  bool modulo_active() const { return params_.modulo_high_counts > params_.modulo_low_counts; }
  void latch_fault(uint32_t bits);
  void motor_off();
  Status begin_motion();
  void start_profile(const Profile& profile, bool stopping);
  uint32_t scan_inputs();
  void follow_position_switches();
  void meet_end_stops();
  void advance_profile();
  void advance_pt();
  void enforce_limits();
  double current_limit_a();
  void close_loop();
  void hold_reference_at_feedback();  // the bridge open: PE 0, the profile at the load
  void check_faults();
  void track_target_window();
  uint32_t step_homing(double position_before_counts);
  bool home_switch_edge() const;  // the edge the homing settings wait for came this cycle
  void home_event(double at_counts);

  // The motor model's per-cycle constants for the current TS (refreshed when TS changes).
  const MotorStep& motor_step();

  MotorModel motor_;
  MotorStep motor_step_;
  double accel_per_amp_counts_per_s2_;  // of motor_, for the acceleration feedforward
  MotorState motor_state_;
  Parameters params_;
  LoopState loop_;

  bool motor_on_ = false;
  bool servo_ready_ = false;
  bool target_set_while_enabling_ = false;  // PA or PR came during the enable delay
  uint32_t enable_elapsed_us_ = 0;
  uint32_t fault_bits_ = 0;
  uint32_t power_stage_codes_ = 0;
  uint32_t fault_causes_ = 0;
  uint32_t pending_events_ = 0;
  uint32_t last_events_ = 0;

  // Motion: positions are internal (motor) counts; user counts = internal + offset.
  double offset_counts_ = 0.0;
  int32_t pa_counts_ = 0;
  int32_t pr_counts_ = 0;
  double target_internal_ = 0.0;
  enum class Pending : uint8_t { kMove, kJog, kPt } pending_ = Pending::kMove;
  bool moving_ = false;
  bool stopping_ = false;  // the profile is a stop (ST, SD): limits need not stop it again
  bool ramping_ = false;   // the profile is still accelerating or decelerating (MS in UM=2)
  // MS=0 needs a point-to-point target the motion reached and the position within TR[1] of it
  // for TR[2]: how long it has been within (-1: it is not).
  bool has_target_ = false;
  int64_t in_window_us_ = -1;
  bool stopped_by_limit_ = false;  // SR bit 28, until the next BG
  bool ends_at_limit_ = false;     // the motion's end is a VH[3]/VL[3] limit, not its target
  PtTable pt_;
  int32_t pt_start_ = 1;
  bool pt_active_ = false;
  MotionKind motion_kind_ = MotionKind::kNone;
  int32_t pt_executing_ = 1;
  double pt_offset_counts_ = 0.0;  // user-to-internal at the PT start
  Profile profile_;
  double profile_duration_s_ = 0.0;  // profile_.duration_s(), summed once per profile
  uint64_t profile_start_cycle_ = 0;
  ProfileSample raw_{0.0, 0.0, 0.0};  // the profile before smoothing
  ProfileSample ref_{0.0, 0.0, 0.0};  // the reference the loops follow
  MovingAverage smooth_position_, smooth_velocity_, smooth_accel_;
  float torque_command_a_ = 0.0f;
  double current_command_a_ = 0.0;
  double velocity_command_counts_per_s_ = 0.0;
  double above_continuous_s_ = 0.0;

  uint32_t input_levels_ = 0;  // input n's level is bit n-1 (firmware reads them every cycle)
  bool level_bit(int n) const { return (input_levels_ >> (n - 1)) & 1u; }
  void set_level_bit(int n, bool high) {
    input_levels_ = (input_levels_ & ~(1u << (n - 1))) | (high ? 1u << (n - 1) : 0u);
  }
  std::array<bool, kInputCount> input_was_active_{};
  // scan_inputs runs only when an input or its IL may have changed, or an inhibit holds the
  // motor off; it leaves here what enforce_limits needs, so the usual cycle reads no input.
  bool inputs_changed_ = true;
  bool inhibit_active_ = false;
  bool forward_limit_active_ = false;
  bool reverse_limit_active_ = false;
  bool hard_stop_active_ = false;
  bool home_input_rose_ = false;  // this cycle's scan saw a main-home input become active
  uint32_t inputs_rose_ = 0;      // this cycle's scan: bit n-1, input n became active
  uint32_t inputs_fell_ = 0;      // this cycle's scan: bit n-1, input n became inactive
  uint32_t outputs_ = 0;

  std::array<PositionSwitch, kInputCount> switches_{};
  bool any_switch_ = false;
  double index_offset_counts_ = 0.0;
  EndStops end_stops_;
  HomingSettings homing_settings_;
  Homing homing_;
  int32_t home_capture_ = 0;
  uint32_t home_events_ = 0;
  int32_t aux_position_counts_ = 0;

  uint32_t time_us_ = 0;
  uint64_t cycles_ = 0;
  Recorder recorder_;
};

}  // namespace uprog::drive
