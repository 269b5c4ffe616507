// The AG300's keywords mapped onto the drive (drive::Axis) and the firmware's own state: what a
// parameter reads and takes, what a command does, and the statuses of AWaitStatus/AGetStatus.
#include <fmt/core.h>

#include "dialects/pup/firmware.h"
#include "drive/axis.h"

namespace uprog::pup {
namespace {

int32_t code_of(drive::Status s) {
  switch (s) {
    case drive::Status::kOk:
      return 0;
    case drive::Status::kOutOfRange:
      return 10;
    case drive::Status::kMotorOn:
      return 22;
    case drive::Status::kMotorOff:
      return 21;
    case drive::Status::kFaultLatched:
      return 23;
    case drive::Status::kInhibitActive:
      return 24;
    case drive::Status::kModeNotSupported:
    case drive::Status::kBadStartData:
      return 25;
  }
  return 10;
}

int32_t positive(int32_t v, int32_t& field) {
  if (v <= 0) return 10;
  field = v;
  return 0;
}

}  // namespace

int32_t Firmware::read_key(KeywordId key, int32_t index, int32_t& out) {
  drive::Axis& a = *axis_;
  const drive::Parameters& p = a.parameters();
  switch (key) {
    case KeywordId::MotorOn:
      out = a.motor_on() ? 1 : 0;
      return 0;
    case KeywordId::MotorReady:
      out = a.servo_ready() ? 1 : 0;
      return 0;
    case KeywordId::MotionMode:
      out = motion_mode_;
      return 0;
    case KeywordId::AbsTrgt:
      out = abs_trgt_;
      return 0;
    case KeywordId::RelTrgt:
      out = rel_trgt_;
      return 0;
    case KeywordId::CurrCmd:
      out = curr_cmd_;
      return 0;
    case KeywordId::Pos:
      out = a.position();
      return 0;
    case KeywordId::Speed:
      out = speed_;
      return 0;
    case KeywordId::Accel:
      out = p.accel_counts_per_s2;
      return 0;
    case KeywordId::Decel:
      out = p.decel_counts_per_s2;
      return 0;
    case KeywordId::StopDecel:
      out = p.stop_decel_counts_per_s2;
      return 0;
    case KeywordId::Smooth:
      out = p.smoothing_ms;
      return 0;
    case KeywordId::Vel:
      out = a.velocity();
      return 0;
    case KeywordId::PosErr:
      out = a.position_error();
      return 0;
    case KeywordId::PosRef:
      out = a.reference_position();
      return 0;
    case KeywordId::InMotion:
      out = a.profiler_moving() ? 1 : 0;
      return 0;
    case KeywordId::InPos:
      out = a.motion_status() == 0 ? 1 : 0;
      return 0;
    case KeywordId::PosMax:
      out = p.position_high_counts;
      return 0;
    case KeywordId::PosMin:
      out = p.position_low_counts;
      return 0;
    case KeywordId::MaxPosErr:
      out = p.max_position_error_counts;
      return 0;
    case KeywordId::MotorFault:
      out = static_cast<int32_t>(a.motor_fault());
      return 0;
    case KeywordId::DinPort:
    case KeywordId::InPort:
      out = static_cast<int32_t>(a.input_level_bits());
      return 0;
    case KeywordId::DoutPort:
    case KeywordId::OutPort:
      out = static_cast<int32_t>(a.output_port());
      return 0;
    case KeywordId::InFunc:
      out = in_func_[static_cast<size_t>(index - 1)];
      return 0;
    case KeywordId::AinPort:
      out = analog_mv_;
      return 0;
    case KeywordId::AinFactor:
      out = ain_factor_;
      return 0;
    case KeywordId::AinOffset:
      out = ain_offset_;
      return 0;
    case KeywordId::GenData:
      out = gen_data_[static_cast<size_t>(index - 1)].i;
      return 0;
    case KeywordId::Timer:
      out = timers_[static_cast<size_t>(index - 1)];
      return 0;
    case KeywordId::Time:
      out = static_cast<int32_t>(runtime_.now_ns() / 1'000'000);
      return 0;
    case KeywordId::ProgStatus:
      out = program_status(static_cast<uint32_t>(index));
      return 0;
    case KeywordId::ProgError:
      out = thread_error_[static_cast<size_t>(index)];
      return 0;
    case KeywordId::ProgPriority:
      out = static_cast<int32_t>(schedule_.priority(static_cast<uint32_t>(index)));
      return 0;
    case KeywordId::ProgEventMask:
      out = static_cast<int32_t>(event_mask_);
      return 0;
    case KeywordId::ProgPointer:
      if (!program_) return 15;
      out = program_status(static_cast<uint32_t>(index)) == 0
                ? 0
                : static_cast<int32_t>(next_line(static_cast<uint32_t>(index)));
      return 0;
    default:
      return 8;  // no single value: lists are the command line's (command_line.cpp)
  }
}

int32_t Firmware::write_key(KeywordId key, int32_t index, int32_t value) {
  drive::Axis& a = *axis_;
  drive::Parameters& p = a.parameters();
  const bool moving = a.profiler_moving();
  switch (key) {
    case KeywordId::MotorOn:
      if (value != 0 && value != 1) return 10;
      return code_of(a.set_motor_on(value == 1));
    case KeywordId::MotionMode:
      if (moving) return 20;
      return set_motion_mode(value);
    // The targets take effect at ABegin (modes 0 and 1), as the mode decides which one moves.
    case KeywordId::AbsTrgt:
      abs_trgt_ = value;
      return 0;
    case KeywordId::RelTrgt:
      rel_trgt_ = value;
      return 0;
    case KeywordId::CurrCmd:
      // mA; the drive clamps the current to its limit. It drives the motor in mode 4 only.
      curr_cmd_ = value;
      a.set_torque_command(static_cast<float>(value) / 1000.0f);
      return 0;
    case KeywordId::InFunc:
      return set_input_function(index, value);
    case KeywordId::Pos:
      if (moving) return 20;
      a.set_position(value);
      return 0;
    case KeywordId::Speed:
      if (value == 0 || value > 2'000'000 || value < -2'000'000) return 10;
      speed_ = value;
      return 0;
    case KeywordId::Accel:
      return positive(value, p.accel_counts_per_s2);
    case KeywordId::Decel:
      return positive(value, p.decel_counts_per_s2);
    case KeywordId::StopDecel:
      return positive(value, p.stop_decel_counts_per_s2);
    case KeywordId::Smooth:
      if (value < 0) return 10;
      p.smoothing_ms = value;
      return 0;
    case KeywordId::PosMax:
      p.position_high_counts = value;
      return 0;
    case KeywordId::PosMin:
      p.position_low_counts = value;
      return 0;
    case KeywordId::MaxPosErr:
      return positive(value, p.max_position_error_counts);
    case KeywordId::DoutPort:
    case KeywordId::OutPort:
      if (value < 0 || value > 15) return 10;
      a.set_output_port(static_cast<uint32_t>(value));
      return 0;
    case KeywordId::AinFactor:
      ain_factor_ = value;
      return 0;
    case KeywordId::AinOffset:
      ain_offset_ = value;
      return 0;
    case KeywordId::GenData:
      gen_data_[static_cast<size_t>(index - 1)] = Value::of_int(value);
      return 0;
    case KeywordId::Timer:
      timers_[static_cast<size_t>(index - 1)] = value;
      return 0;
    case KeywordId::ProgPriority:
      return schedule_.set_priority(static_cast<uint32_t>(index), static_cast<uint32_t>(value))
                 ? 0
                 : 10;
    case KeywordId::ProgEventMask:
      event_mask_ = static_cast<uint32_t>(value);
      return 0;
    case KeywordId::ProgBreaks:
      return program_ ? set_breaks(static_cast<uint32_t>(index), value) : 15;
    case KeywordId::ProgPointer:
      return set_pointer(static_cast<uint32_t>(index), value);
    default:
      return 11;
  }
}

int32_t Firmware::run_key(KeywordId key, int32_t index, bool, int32_t arg, uint32_t thread) {
  drive::Axis& a = *axis_;
  switch (key) {
    case KeywordId::Begin: {
      drive::Parameters& p = a.parameters();
      if (motion_mode_ == 4) return 25;  // the current loop has no motion to begin
      if (!a.motor_on()) return 21;
      p.speed_counts_per_s = speed_ < 0 ? -speed_ : speed_;
      switch (motion_mode_) {
        case 0:
          a.set_absolute_target(abs_trgt_);
          break;
        case 1:
          a.set_relative_move(rel_trgt_);
          break;
        default:
          a.set_jog_velocity(speed_);
          break;  // 2 a position-loop jog, 3 the velocity loop
      }
      return code_of(a.begin());
    }
    case KeywordId::Stop:
      a.stop();
      return 0;
    case KeywordId::ClearFault:
      return a.motor_fault() == 0 ? 0 : 23;  // the drive keeps a latched fault
    case KeywordId::ProgRun: {
      const uint32_t t = static_cast<uint32_t>(index);
      if (arg == -1) {
        if (!program_) return 15;
        const int32_t s = program_status(t);
        if (s == 6) return schedule_.release(t), 0;
        if (s != 3 && s != 4) return 19;
        program_->machine().resume(t);
        return 0;
      }
      return run_task(t, arg);
    }
    case KeywordId::ProgHalt: {
      if (!program_) return 15;
      const int32_t s = program_status(static_cast<uint32_t>(index));
      if (s != 1 && s != 2 && s != 6) return 18;
      program_->machine().halt(static_cast<uint32_t>(index));
      return thread == static_cast<uint32_t>(index) ? vm::kCommandEndSlice : 0;
    }
    case KeywordId::ProgHaltAll:
      if (!program_) return 0;
      for (uint32_t t = 1; t <= kThreads; ++t) {
        const int32_t s = program_status(t);
        if (s == 1 || s == 2 || s == 6) program_->machine().halt(t);
      }
      return thread != 0 ? vm::kCommandEndSlice : 0;
    case KeywordId::ProgResetAll:
      if (program_) {
        for (uint32_t t = 1; t <= kThreads; ++t) {
          if (t == thread)
            program_->machine().halt(t);
          else
            program_->machine().kill(t);
          set_breaks(t, 0);
          stepping_ &= ~(1u << t);
        }
      }
      schedule_.reset();
      thread_error_.fill(0);
      event_mask_ = 0x00FFFFFF;
      latched_ = 0;
      event_frames_.clear();
      line_stack_.clear();  // "... or upon resetting the user program" (the manual)
      return thread != 0 ? vm::kCommandEndSlice : 0;
    case KeywordId::ProgSingle:
      return program_ ? single_step(static_cast<uint32_t>(index), arg) : 15;
    case KeywordId::ProgClrCall:
      return clear_stacks(static_cast<uint32_t>(index), false);
    case KeywordId::ProgClrExp:
      return clear_stacks(static_cast<uint32_t>(index), true);
    default:
      return 8;
  }
}

namespace {
// The drive's unit mode (UM) of each AMotionMode: 0..2 the position loop, 3 velocity, 4 current.
int32_t unit_mode_of(int32_t mode) { return mode <= 2 ? 5 : mode == 3 ? 2 : 1; }
}  // namespace

// AMotionMode: a mode of another loop (0-2, 3, 4) switches the drive's loop, which it takes
// only with the motor off (22).
int32_t Firmware::set_motion_mode(int32_t mode) {
  if (mode < 0 || mode > 4) return 10;
  drive::Axis& a = *axis_;
  const int32_t unit = unit_mode_of(mode);
  if (a.parameters().unit_mode != unit) {
    if (a.motor_on()) return 22;
    if (const int32_t c = code_of(a.set_unit_mode(unit)); c != 0) return c;
  }
  motion_mode_ = mode;
  return 0;
}

// AInFunc[n]: 0 general purpose, 1 forward limit, 2 reverse limit, 3 inhibit, 4 hard stop, all
// active high, as the drive's input logic (IL) of that function with the odd (high) polarity.
int32_t Firmware::set_input_function(int32_t n, int32_t function) {
  static constexpr int32_t kLogic[] = {7, 11, 9, 1, 3};
  if (function < 0 || function > 4) return 10;
  if (const int32_t c = code_of(axis_->set_input_logic(n, kLogic[function])); c != 0) return c;
  in_func_[static_cast<size_t>(n - 1)] = function;
  return 0;
}

// `analog = MV` sets the analog input AAINPort reads; `comm-error` is a line the framer refused
// (event 23; the transcript expects no answer from it).
bool Firmware::world_directive(std::string_view name, std::string_view arg, std::string& failure) {
  if (name == "analog") {
    std::string_view v = arg;
    if (!v.empty() && v.front() == '=') v.remove_prefix(1);
    while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
    const auto mv = parse_number(v);
    if (!mv)
      failure = "analog needs 'analog = MV' (an integer, mV)";
    else
      analog_mv_ = *mv;
    return true;
  }
  if (name == "comm-error") {
    if (!arg.empty())
      failure = "comm-error takes no argument";
    else
      on_framing_error(900);  // as a line too long
    return true;
  }
  return false;
}

// AWaitStatus/AGetStatus: 1 or 0, or minus the error code.
int32_t Firmware::status_of(int32_t s, int32_t v) {
  const drive::Axis& a = *axis_;
  auto flag = [](bool b) { return b ? 1 : 0; };
  switch (s) {
    case 1:
      return flag(!a.profiler_moving());
    case 2:
      return flag(a.motion_status() == 0);
    case 8:
      return flag(a.servo_ready());
    case 3:
    case 4:
      if (v < 1 || v > 6) return -7;
      return flag(a.input_level(v) == (s == 3));
    case 5:
    case 6:
      if (v < 1 || v > 1000) return -7;
      return flag((gen_data_[static_cast<size_t>(v - 1)].i != 0) == (s == 5));
    case 7:
      if (v < 1 || v > 4) return -7;
      return flag(timers_[static_cast<size_t>(v - 1)] == 0);
    case 9:
      if (v < 1 || v > 8) return -7;
      return flag(program_status(static_cast<uint32_t>(v)) != 1 &&
                  program_status(static_cast<uint32_t>(v)) != 2);
    default:
      return -4;
  }
}

}  // namespace uprog::pup
