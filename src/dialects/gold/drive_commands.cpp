// One switch per direction (read, write, execute) from a Gold command id to the axis; the
// commands from the Elmo reference (ids 57 on) have a switch of their own below.
#include "dialects/gold/drive_commands.h"

#include <cmath>

#include "dialects/gold/homing_events.h"
#include "drive/faults.h"
#include "drive/parameters.h"

namespace uprog::gold {
namespace {

// Ids of commands.cpp; drive_commands_test checks that each matches its name.
enum Id : uint16_t {
  MO = 1,
  SO,
  UM,
  PA,
  PR,
  SP,
  AC,
  DC,
  SD,
  SF,
  JV,
  BG,
  ST,
  TC,
  PX,
  VX,
  PE,
  DV,
  MS,
  ER,
  VH,
  VL,
  XM,
  KP,
  KI,
  KV,
  CL,
  PL,
  IL,
  IP,
  IB,
  OP,
  OB,
  MF,
  SR,
  TM,
  TS,
  UI,
  UF,
  SV,
  LD,
  RS,
  MI,
  XQ,
  HP,
  XC,
  KL,
  PS,
  CC,
  LS,
  EC,
  DB,
  RV,
  RL,
  RG,
  RR,
  HM,
  CA,
  QP,
  TR,
  TI,
  WS,
  EO,
  LL,
  HL,
  FP,
  FV,
  VR,
  SN,
  MP,
  PT,
  PY,
  PM,
  IQ,
  HX,
  RC,
  RP,
  WI,
  BH,
  RM,
  ID,
  FC,
  BP,
  SC,
  FS,
  OV,
  LC,
};

bool from_reference(uint16_t id) { return id >= HM; }

// HM[n]: the index's own range (docs/dialects/gold.md, "Homing").
bool homing_value_in_range(int32_t index, int32_t v) {
  switch (index) {
    case 1:
      return v == 0 || v == 1;
    case 3: {
      drive::HomingSettings probe;
      return set_home_event(v, probe);
    }
    case 4:
      return v >= 0 && v <= drive::kHomeActionMax;
    case 5:
      return v >= 0 && v <= drive::kHomePositionSettingMax;
    case 6:
      return v >= 0 && v <= drive::kOutputCount;
    default:
      return true;  // HM[2] takes any position
  }
}

// The commands the controller serves (handled_by_drive is false for them).
bool controller_command(uint16_t id) {
  switch (id) {
    case SV:
    case LD:
    case RS:
    case MI:
    case XQ:
    case HP:
    case XC:
    case KL:
    case PS:
    case CC:
    case LS:
    case EC:
    case DB:
      return true;
    default:
      return false;
  }
}

// Common checks of read and write: the command exists, is the drive's, and the index fits.
int32_t check(uint16_t id, int32_t index, const CommandInfo*& info) {
  info = find_command(id);
  if (info == nullptr) return kErrorBadCommand;
  if (controller_command(id)) return kErrorNotHandledHere;
  if (info->flags & kIndexed) {
    if (index == 0 && (info->flags & kIndexOptional)) return kDriveOk;  // SF is SF[1]
    if (index < info->min_index || index > info->max_index) return kErrorBadIndex;
  } else if (index != 0) {
    return kErrorBadIndex;
  }
  return kDriveOk;
}

bool in_range(const CommandInfo& info, Value value) {
  if (info.type == ValueType::Float) {
    const double f = value.f;
    return !std::isnan(f) && f >= info.min_value && f <= info.max_value;
  }
  const double i = value.i;
  return i >= info.min_value && i <= info.max_value;
}

size_t slot(int32_t index) { return static_cast<size_t>(index - 1); }

// OV[2]: the motion mode of the motion BG began (docs/dialects/gold.md, "Preflight").
int32_t motion_mode(drive::Axis::MotionKind kind) {
  switch (kind) {
    case drive::Axis::MotionKind::kPointToPoint:
      return 1;
    case drive::Axis::MotionKind::kPt:
      return 2;
    case drive::Axis::MotionKind::kJog:
      return 3;
    case drive::Axis::MotionKind::kNone:
      break;
  }
  return 0;
}

}  // namespace

bool handled_by_drive(uint16_t id) {
  return !controller_command(id) && find_command(id) != nullptr;
}

int32_t error_for(drive::Status status) {
  switch (status) {
    case drive::Status::kOk:
      return kDriveOk;
    case drive::Status::kOutOfRange:
      return kErrorOutOfRange;
    case drive::Status::kMotorOn:
      return kErrorMotorMustBeOff;
    case drive::Status::kMotorOff:
      return kErrorMotorMustBeOn;
    case drive::Status::kFaultLatched:
      return kErrorFaultPresent;
    case drive::Status::kInhibitActive:
      return kErrorInhibitActive;
    case drive::Status::kModeNotSupported:
      return kErrorModeNotSupported;
    case drive::Status::kBadStartData:
      return kErrorBadStartData;
  }
  return kErrorBadCommand;
}

int32_t DriveCommands::read(uint16_t id, int32_t index, Value& out) {
  const CommandInfo* info = nullptr;
  if (const int32_t e = check(id, index, info)) return e;
  if (info->flags & kAction) return kErrorNoValue;
  const drive::Parameters& p = axis_.parameters();
  auto i = [&](int32_t v) {
    out = Value::of_int(v);
    return kDriveOk;
  };
  auto f = [&](float v) {
    out = Value::of_float(v);
    return kDriveOk;
  };
  switch (id) {
    case MO:
      return i(axis_.motor_on() ? 1 : 0);
    case SO:
      return i(axis_.servo_ready() ? 1 : 0);
    case UM:
      return i(p.unit_mode);
    case PA:
      return i(axis_.absolute_target());
    case PR:
      return i(axis_.relative_move());
    case SP:
      return i(p.speed_counts_per_s);
    case AC:
      return i(p.accel_counts_per_s2);
    case DC:
      return i(p.decel_counts_per_s2);
    case SD:
      return i(p.stop_decel_counts_per_s2);
    case SF:
      return i(index == 2 ? p.smoothing2_ms : p.smoothing_ms);
    case JV:
      return i(p.jog_velocity_counts_per_s);
    case TC:
      return f(axis_.torque_command());
    case PX:
      return i(axis_.position());
    case VX:
      return i(axis_.velocity());
    case PE:
      return i(axis_.position_error());
    case DV:
      return i(index == 2 ? axis_.reference_velocity() : axis_.reference_position());
    case MS:
      return i(axis_.motion_status());
    case ER:
      return i(index == 2 ? p.max_velocity_error_counts_per_s : p.max_position_error_counts);
    case VH:
      return i(index == 2 ? p.velocity_high_counts_per_s : p.position_high_counts);
    case VL:
      return i(index == 2 ? p.velocity_low_counts_per_s : p.position_low_counts);
    case XM:
      return i(index == 1 ? p.modulo_low_counts : p.modulo_high_counts);
    case KP:
      return f(p.gains.kp[index]);
    case KI:
      return f(p.gains.ki[index]);
    case KV:
      return f(p.gains.kv[index]);
    case CL:
      return f(p.continuous_current_a);
    case PL:
      return f(p.peak_current_a);
    case IL:
      return i(p.input_logic[slot(index)]);
    case IP:
      return i(static_cast<int32_t>(axis_.input_port()));
    case IB:
      return i(static_cast<int32_t>((axis_.input_port() >> index) & 1u));
    case OP:
      return i(static_cast<int32_t>(axis_.output_port()));
    case OB:
      return i(axis_.output(index) ? 1 : 0);
    case MF:
      return i(static_cast<int32_t>(axis_.motor_fault()));
    case SR:
      return i(static_cast<int32_t>(status_register()));
    case TM:
      return i(static_cast<int32_t>(axis_.time_us()));
    case TS:
      return i(p.servo_period_us);
    case UI:
      return i(p.user_ints[slot(index)]);
    case UF:
      return f(p.user_floats[slot(index)]);
    default:  // after the feedback a program polls every cycle
      if (RecorderCommands::serves(id)) return recorder_.read(id, index, out);
      if (from_reference(id)) return read_reference(id, index, out);
      return kErrorBadCommand;
  }
}

int32_t DriveCommands::write(uint16_t id, int32_t index, Value value) {
  const CommandInfo* info = nullptr;
  if (const int32_t e = check(id, index, info)) return e;
  if (info->flags & kAction) return kErrorNotAssignable;
  if (info->flags & kReadOnly) return kErrorReadOnly;
  if (!in_range(*info, value)) return kErrorOutOfRange;
  if ((info->flags & kMotorOffOnly) && axis_.motor_on()) return kErrorMotorMustBeOff;
  if (RecorderCommands::serves(id)) return recorder_.write(id, index, value);
  if (from_reference(id)) return write_reference(id, index, value);
  drive::Parameters& p = axis_.parameters();
  const int32_t v = value.i;
  switch (id) {
    case MO:
      return error_for(axis_.set_motor_on(v == 1));
    case UM:
      return error_for(axis_.set_unit_mode(v));
    case PA:
      axis_.set_absolute_target(v);
      break;
    case PR:
      axis_.set_relative_move(v);
      break;
    case SP:
      p.speed_counts_per_s = v;
      break;
    case AC:
      p.accel_counts_per_s2 = v;
      break;
    case DC:
      p.decel_counts_per_s2 = v;
      break;
    case SD:
      p.stop_decel_counts_per_s2 = v;
      break;
    case SF:
      (index == 2 ? p.smoothing2_ms : p.smoothing_ms) = v;
      break;
    case JV:
      axis_.set_jog_velocity(v);
      break;
    case TC:
      axis_.set_torque_command(value.f);
      break;
    case PX:
      axis_.set_position(v);
      break;
    case ER:
      (index == 2 ? p.max_velocity_error_counts_per_s : p.max_position_error_counts) = v;
      break;
    case VH:
      (index == 2 ? p.velocity_high_counts_per_s : p.position_high_counts) = v;
      break;
    case VL:
      (index == 2 ? p.velocity_low_counts_per_s : p.position_low_counts) = v;
      break;
    case XM:
      (index == 1 ? p.modulo_low_counts : p.modulo_high_counts) = v;
      break;
    case KP:
      p.gains.kp[index] = value.f;
      break;
    case KI:
      p.gains.ki[index] = value.f;
      break;
    case KV:
      p.gains.kv[index] = value.f;
      break;
    case CL:
      p.continuous_current_a = value.f;
      break;
    case PL:
      p.peak_current_a = value.f;
      break;
    case IL:
      return error_for(axis_.set_input_logic(index, v));
    case OP:
      axis_.set_output_port(static_cast<uint32_t>(v));
      break;
    case OB:
      axis_.set_output(index, v == 1);
      break;
    case TM:
      axis_.set_time_us(static_cast<uint32_t>(v));
      break;
    case TS:
      return error_for(axis_.set_period_us(v));
    case UI:
      p.user_ints[slot(index)] = v;
      break;
    case UF:
      p.user_floats[slot(index)] = value.f;
      break;
    default:
      return kErrorBadCommand;
  }
  return kDriveOk;
}

uint32_t DriveCommands::status_register() const {
  uint32_t sr = axis_.status_register() | recorder_.status_bits();
  if (program_state_) {
    const ProgramState state = program_state_();
    if (state.running) sr |= drive::kSrProgramRunning;
    if (state.error) sr |= drive::kSrProgramError;
  }
  return sr;
}

std::optional<std::string> DriveCommands::text(uint16_t id) const {
  if (id != VR) return std::nullopt;
  return std::string(kVersionText);
}

int32_t DriveCommands::read_reference(uint16_t id, int32_t index, Value& out) {
  const drive::Parameters& p = axis_.parameters();
  const drive::HomingSettings& h = axis_.homing_settings();
  auto i = [&](int32_t v) {
    out = Value::of_int(v);
    return kDriveOk;
  };
  switch (id) {
    case HM:
      switch (index) {
        case 1:
          return i(axis_.homing_armed() ? 1 : 0);
        case 2:
          return i(h.home_value_counts);
        case 3:
          return i(home_event_code(h));
        case 4:
          return i(static_cast<int32_t>(h.action));
        case 5:
          return i(static_cast<int32_t>(h.setting));
        case 6:
          return i(h.output);
        default:
          return i(axis_.home_capture());
      }
    case CA:
      return i(p.commutation[slot(index)]);
    case QP:
      return i(axis_.pt_table().positions[slot(index)]);
    case TR:
      return i(index == 1 ? p.target_radius_counts : p.target_time_ms);
    case TI:
      return i(kTemperature_c);
    case WS: {
      if (index != 21) return i(0);  // system words the simulated drive does not model
      // The reference's commutation formula: WS[21] = mod(encoder, CA[18]).
      const int64_t counts = p.counts_per_revolution();
      if (counts < 1) return i(0);  // only a loaded parameter file can hold such a CA[18]
      const int64_t m = ((static_cast<int64_t>(axis_.position()) % counts) + counts) % counts;
      return i(static_cast<int32_t>(m));
    }
    case EO:
      return i(echo_);
    case LL:
      return i(index == 2 ? p.speed_fault_low_counts_per_s : p.position_fault_low_counts);
    case HL:
      return i(index == 2 ? p.speed_fault_high_counts_per_s : p.position_fault_high_counts);
    case FP:
      return i(index == 1 ? axis_.position() : axis_.aux_position());
    case FV:
      return i(index == 1 ? axis_.velocity() : 0);  // no auxiliary encoder: it stands still
    case VR:
      return kErrorNoValue;  // text: the command line answers it with text()
    case SN:
      return i(kIdentity[slot(index)]);
    case MP: {
      const drive::PtTable& t = axis_.pt_table();
      switch (index) {
        case 1:
          return i(t.first);
        case 2:
          return i(t.last);
        case 3:
          return i(t.cyclic ? 1 : 0);
        case 4:
          return i(t.cycles_per_point);
        default:
          return i(mp_spare_[slot(index) - 4]);
      }
    }
    case PT:
      return i(axis_.pt_index());
    case PY:
      return i(axis_.aux_position());
    case PM:
      return i(p.profiler_mode);
    case IQ:
      out = Value::of_float(static_cast<float>(axis_.motor_state().current_a));
      return kDriveOk;
    case HX:
      return i(hex_);
    case RM:
      return i(p.reference_mode);
    case ID:
      out = Value::of_float(0.0f);
      return kDriveOk;  // the motor model has no d axis
    case FC:
      return i(p.feedback_config[slot(index)]);
    case BP:
      return i(p.brake_delay_ms[slot(index)]);
    case SC:
      return i(p.stop_config[slot(index)]);
    case FS:
      return i(p.final_speed_counts_per_s);
    case OV:
      return i(motion_mode(axis_.motion_kind()));
    case LC:
      return i((axis_.status_register() & drive::kSrCurrentLimited) != 0 ? 1 : 0);
    default:
      return kErrorBadCommand;
  }
}

int32_t DriveCommands::write_reference(uint16_t id, int32_t index, Value value) {
  drive::Parameters& p = axis_.parameters();
  drive::HomingSettings& h = axis_.homing_settings();
  const int32_t v = value.i;
  switch (id) {
    case HM:
      if (index == 7) return kErrorReadOnly;  // the capture is the drive's
      if (!homing_value_in_range(index, v)) return kErrorOutOfRange;
      switch (index) {
        case 1:
          axis_.arm_homing(v == 1);
          break;
        case 2:
          h.home_value_counts = v;
          break;
        case 3:
          set_home_event(v, h);
          break;
        case 4:
          h.action = static_cast<drive::HomeAction>(v);
          break;
        case 5:
          h.setting = static_cast<drive::HomePositionSetting>(v);
          break;
        default:
          h.output = v;
          break;
      }
      return kDriveOk;
    case CA:
      if (index == drive::kCountsPerRevolutionIndex) {
        // The reference's range for CA[18]: 6..530,000,000 counts.
        if (v > 530000000) return kErrorOutOfRange;
        return error_for(axis_.set_counts_per_revolution(v));
      }
      p.commutation[slot(index)] = v;
      return kDriveOk;
    case QP:
      axis_.pt_table().positions[slot(index)] = v;
      return kDriveOk;
    case TR:
      if (index == 2 && v > 100) return kErrorOutOfRange;  // TR[2]: 0..100 ms
      (index == 1 ? p.target_radius_counts : p.target_time_ms) = v;
      return kDriveOk;
    case EO:
      echo_ = v;
      return kDriveOk;
    case LL:
      (index == 2 ? p.speed_fault_low_counts_per_s : p.position_fault_low_counts) = v;
      return kDriveOk;
    case HL:
      (index == 2 ? p.speed_fault_high_counts_per_s : p.position_fault_high_counts) = v;
      return kDriveOk;
    case MP: {
      drive::PtTable& t = axis_.pt_table();
      switch (index) {
        case 1:
          if (v < 1 || v > drive::kPtPoints) return kErrorOutOfRange;
          t.first = v;
          break;
        case 2:
          if (v < 1 || v > drive::kPtPoints) return kErrorOutOfRange;
          t.last = v;
          break;
        case 3:
          if (v > 1) return kErrorOutOfRange;
          t.cyclic = v == 1;
          break;
        case 4:
          if (v < 1) return kErrorOutOfRange;
          t.cycles_per_point = v;
          break;
        default:
          mp_spare_[slot(index) - 4] = v;
          break;
      }
      return kDriveOk;
    }
    case PT:
      axis_.set_pt_start(v);
      return kDriveOk;
    case PY:
      axis_.set_aux_position(v);
      return kDriveOk;
    case PM:
      p.profiler_mode = v;
      return kDriveOk;
    case HX:
      hex_ = v;
      return kDriveOk;
    case RM:
      p.reference_mode = v;
      return kDriveOk;
    case FC:
      p.feedback_config[slot(index)] = v;
      return kDriveOk;
    case BP:
      p.brake_delay_ms[slot(index)] = v;
      return kDriveOk;
    case SC:
      p.stop_config[slot(index)] = v;
      return kDriveOk;
    case FS:
      p.final_speed_counts_per_s = v;
      return kDriveOk;
    default:
      return kErrorBadCommand;
  }
}

int32_t DriveCommands::execute(uint16_t id, int32_t index) {
  const CommandInfo* info = nullptr;
  if (const int32_t e = check(id, index, info)) return e;
  if (!(info->flags & kAction)) return kErrorNoValue;
  switch (id) {
    case BG:
      return error_for(axis_.begin());
    case ST:
      axis_.stop();
      return kDriveOk;
    default:
      return kErrorBadCommand;
  }
}

}  // namespace uprog::gold
