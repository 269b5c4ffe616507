// One simulated servo axis in virtual time: profile generator, cascaded loops, motor model,
// digital I/O, limits and faults. `step()` advances one servo cycle (TS) and reports events.
// The axis knows physics and parameters, not languages: a dialect maps its commands onto it.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "drive/events.h"
#include "drive/motor_model.h"
#include "drive/parameters.h"
#include "drive/profile.h"
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
  kModeNotSupported,  // BG in UM=1; TC outside UM=1 is accepted but has no effect
};

constexpr uint32_t kEnableDelay_us = 20000;        // MO=1 to SO=1
constexpr double kInPositionWindow_counts = 2.0;    // MS=0 once |PE| is within this
constexpr double kPeakCurrentTime_s = 3.0;          // PL[1] allowed this long, then CL[1]
constexpr double kSpeedLimitMargin = 1.2;           // |VX| beyond margin * VH[2]/VL[2] faults

enum StatusRegisterBits : uint32_t {
  kSrFault = 1u << 0,
  kSrMotorOn = 1u << 4,
  kSrMoving = 1u << 7,
  kSrUnitModeShift = 8,  // bits 8..10
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
  Status set_unit_mode(int32_t mode);           // UM: 1, 2 or 5, motor off only
  Status set_input_logic(int n, int32_t logic); // IL[n]
  Status set_period_us(int32_t period_us);      // TS, 25..2000

  // --- enable ---
  Status set_motor_on(bool on);  // MO
  bool motor_on() const { return motor_on_; }
  bool servo_ready() const { return servo_ready_; }  // SO

  // --- motion ---
  void set_absolute_target(int32_t target_counts);  // PA
  void set_relative_move(int32_t distance_counts);  // PR
  void set_jog_velocity(int32_t velocity_counts_per_s);  // JV
  int32_t absolute_target() const { return pa_counts_; }
  int32_t relative_move() const { return pr_counts_; }
  Status begin();  // BG
  void stop();     // ST: decelerate with DC
  void set_torque_command(float current_a) { torque_command_a_ = current_a; }  // TC
  float torque_command() const { return torque_command_a_; }

  // --- feedback and status ---
  int32_t position() const;                 // PX
  void set_position(int32_t position_counts);
  int32_t velocity() const;                 // VX
  int32_t position_error() const;           // PE
  int32_t reference_velocity() const;       // DV[2]
  int32_t reference_position() const;       // DV[3]
  float current_command() const { return static_cast<float>(current_command_a_); }  // DV[1]
  int32_t motion_status() const;            // MS
  uint32_t status_register() const;         // SR
  uint32_t motor_fault() const { return fault_bits_; }  // MF
  bool profiler_moving() const { return moving_; }

  // --- digital I/O ---
  void set_input_level(int n, bool high);   // the electrical level of input n (1..6)
  bool input_active(int n) const;           // IB[n]
  uint32_t input_port() const;              // IP
  void set_output_port(uint32_t bits) { outputs_ = bits & 0xFu; }  // OP
  uint32_t output_port() const { return outputs_; }
  void set_output(int n, bool on);          // OB[n]
  bool output(int n) const { return ((outputs_ >> (n - 1)) & 1u) != 0; }

  // --- faults ---
  // Latches the named fault (faults.h); with `persistent` its cause stays until
  // clear_fault_cause, and MO=1 is refused meanwhile. False when the name is unknown.
  bool inject_fault(std::string_view name, bool persistent = false);
  void clear_fault_cause(std::string_view name);

  // --- time ---
  uint32_t time_us() const { return time_us_; }  // TM, wraps at 2^32
  void set_time_us(uint32_t t) { time_us_ = t; }
  uint32_t period_us() const { return static_cast<uint32_t>(params_.servo_period_us); }
  uint64_t cycle_count() const { return cycles_; }

  const MotorModel& motor_model() const { return motor_; }
  const MotorState& motor_state() const { return motor_state_; }
  double reference_position_exact() const { return ref_.position_counts; }

 private:
  double dt_s() const { return params_.servo_period_us * 1e-6; }
  double user_to_internal(int64_t user) const;
  int32_t internal_to_user(double internal) const;
  bool modulo_active() const;
  void latch_fault(uint32_t bits);
  void motor_off();
  void start_profile(const Profile& profile, bool stopping);
  void stop_with(double decel_counts_per_s2);
  uint32_t scan_inputs();
  void advance_profile();
  void enforce_limits();
  double current_limit_a();
  void close_loop();

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
  uint32_t enable_elapsed_us_ = 0;
  uint32_t fault_bits_ = 0;
  uint32_t fault_causes_ = 0;
  uint32_t pending_events_ = 0;
  uint32_t last_events_ = 0;

  // Motion: positions are internal (motor) counts; user counts = internal + offset.
  double offset_counts_ = 0.0;
  int32_t pa_counts_ = 0;
  int32_t pr_counts_ = 0;
  double target_internal_ = 0.0;
  enum class Pending : uint8_t { kMove, kJog } pending_ = Pending::kMove;
  bool moving_ = false;
  bool stopping_ = false;  // the profile is a stop (ST, SD): limits need not stop it again
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

  std::array<bool, kInputCount> input_levels_{};
  std::array<bool, kInputCount> input_was_active_{};
  // scan_inputs runs only when an input or its IL may have changed, or an inhibit holds the
  // motor off; it leaves here what enforce_limits needs, so the usual cycle reads no input.
  bool inputs_changed_ = true;
  std::array<int32_t, kInputCount> scanned_logic_{};  // IL as last scanned
  bool inhibit_active_ = false;
  bool forward_limit_active_ = false;
  bool reverse_limit_active_ = false;
  bool hard_stop_active_ = false;
  uint32_t outputs_ = 0;

  uint32_t time_us_ = 0;
  uint64_t cycles_ = 0;
};

}  // namespace uprog::drive
