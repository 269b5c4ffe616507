// Maps the Gold drive commands (commands.h) onto a drive::Axis: reads, writes and actions by
// command id and index, each refused with a Gold-style error code
// (docs/dialects/gold-drive-errors.md). Program-control commands belong to the controller and come
// back as kErrorNotHandledHere.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "dialects/gold/commands.h"
#include "dialects/gold/recorder_commands.h"
#include "drive/axis.h"
#include "support/value.h"

namespace uprog::gold {

// The interpreter's error codes for drive commands (EC). Numbers follow the Elmo EC table
// where it has a matching entry.
enum DriveError : int32_t {
  kDriveOk = 0,
  kErrorBadCommand = 2,         // no command with that id
  kErrorBadIndex = 3,           // index outside the command's range, or an index it does not take
  kErrorNoValue = 5,            // an action read as a value, or a non-action executed
  kErrorBadStartData = 7,       // reference EC 7 "Mode cannot be started - bad initialization
                                // data": BG of a PT motion whose PT lies outside MP[1]..MP[2]
  kErrorOutOfRange = 21,        // the value is outside the command's range
  kErrorNotAssignable = 23,     // an action given a value (BG=1)
  kErrorModeNotSupported = 26,  // BG in unit mode 1
  kErrorReadOnly = 43,          // a status assigned (VX=0)
  kErrorMotorMustBeOn = 57,     // BG while MO=0
  kErrorMotorMustBeOff = 60,    // UM while MO=1
  kErrorFaultPresent = 64,      // MO=1 while a fault's cause is present
  kErrorInhibitActive = 65,     // MO=1 while an inhibit input is active
  kErrorNotHandledHere = 1000,  // a controller command (XQ, MI, PS, SV, ...): the caller handles it
};

// True for the commands this class serves; the others (program control, MI, PS, EC, SV, LD,
// RS, DB) are the controller's.
bool handled_by_drive(uint16_t id);

// What SR reports of the user program (bits 12 and 29); the program's host knows it.
struct ProgramState {
  bool running = false;  // SR bit 12
  bool error = false;    // SR bit 29: the program stopped on an error
};
using ProgramStateSource = std::function<ProgramState()>;

// The simulated drive's identity (VR, SN): docs/dialects/gold.md, "Identity".
inline constexpr std::string_view kVersionText = "uprog simulated Gold drive 1.0";
inline constexpr std::array<int32_t, 4> kIdentity{154, 0x55505247, 0x00010000, 1};  // SN[1..4]
inline constexpr int32_t kTemperature_c = 25;  // TI[n]: no thermal model, ambient

class DriveCommands {
 public:
  explicit DriveCommands(drive::Axis& axis) : axis_(axis), recorder_(axis) {}

  // SR's program bits come from here; without a source they read 0.
  void set_program_state_source(ProgramStateSource source) { program_state_ = std::move(source); }
  // SR as a host reads it: the axis's bits and the program's.
  uint32_t status_register() const;
  // The text of a kText command (VR); nullopt for any other id.
  std::optional<std::string> text(uint16_t id) const;
  // EO and HX as the wire needs them (the transport echoes and formats; docs/dialects/gold.md).
  bool echo() const { return echo_ != 0; }
  bool hexadecimal() const { return hex_ != 0; }

  // `index` is the manual's index (UI[1] -> 1); non-indexed commands take 0.
  int32_t read(uint16_t id, int32_t index, Value& out);
  // `value` is already converted to the command's type (commands.h).
  int32_t write(uint16_t id, int32_t index, Value value);
  int32_t execute(uint16_t id, int32_t index);

  // RV, RC, RL, RG, RP, RR (recorder_commands.h); DB##RV[n] maps its variables.
  RecorderCommands& recorder() { return recorder_; }

 private:
  int32_t read_reference(uint16_t id, int32_t index, Value& out);
  int32_t write_reference(uint16_t id, int32_t index, Value value);

  drive::Axis& axis_;
  RecorderCommands recorder_;
  ProgramStateSource program_state_;
  int32_t echo_ = 1;                   // EO: a real drive echoes until the host sends EO=0
  int32_t hex_ = 0;                    // HX
  std::array<int32_t, 2> mp_spare_{};  // MP[5], MP[6]: stored, no effect
};

// The Gold code for a refusal of the axis.
int32_t error_for(drive::Status status);

}  // namespace uprog::gold
