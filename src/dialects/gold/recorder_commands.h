// Gold's recorder commands (RC, RV[n], RL, RG, RP[n], RR, and RR's status in SR bits 16-17) as
// the Elmo SimplIQ Command Reference and Software Manual chapter 7.4 define them, on the drive's
// recorder (drive/recorder.h); docs/dialects/gold.md, "The recorder", lists the decisions.
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "drive/axis.h"
#include "support/value.h"

namespace uprog::gold {

// The recorder's own refusals (interpreter_errors.def); the reference pages give them no number,
// these are uprog's, after the command line's own.
constexpr int32_t kErrorRecorderBusy = 214;  // RC, RV, RL, RG, RP changed while recording
constexpr int32_t kErrorRecorderNoSignals =
    215;                                       // RR=1..3 with no signal in RC, or RP[1] off RC's RV
constexpr int32_t kErrorRecorderNoData = 216;  // BH while no complete recording is held

constexpr size_t kRecorderSlots = 8;        // RV[1..8], RC bits 0..7
constexpr size_t kRecorderParameters = 10;  // RP[0..9]

class RecorderCommands {
 public:
  // Ids of commands.cpp (gold_recorder_commands_test checks them against the names).
  enum Id : uint16_t { RV = 53, RL = 54, RG = 55, RR = 56, RC = 76, RP = 77, WI = 78 };

  explicit RecorderCommands(drive::Axis& axis) : axis_(axis) {}
  // The ids of commands.cpp this class serves: RV, RL, RG, RR, RC, RP, WI. Inline: every command
  // a program reads asks it.
  static bool serves(uint16_t id) {
    return id == RV || id == RL || id == RG || id == RR || id == RC || id == RP || id == WI;
  }
  int32_t read(uint16_t id, int32_t index, Value& out) const;
  int32_t write(uint16_t id, int32_t index, Value value);
  // DB##RV[n]=name: slot n records the program's global `name` (or `name[i]`).
  void map_variable(int32_t n, std::string name);
  // SR bits 16 and 17 (Software Manual table 7-5).
  uint32_t status_bits() const;
  // BH=n (Software Manual 7.4.7): the signal RC&n's lowest bit names, as the hexadecimal record
  // of table 8-8 in `out`; else the refusal's code.
  int32_t upload(int32_t n, std::string& out) const;
  // WI[21]: the samples per signal recorded so far.
  int32_t samples_recorded() const;

 private:
  int32_t launch(int32_t mode);
  int32_t channel_of(size_t slot, drive::Channel& out) const;
  uint32_t report() const;

  drive::Axis& axis_;
  std::array<int32_t, kRecorderSlots> signals_{};        // RV[n]
  std::array<std::string, kRecorderSlots> variables_{};  // DB##RV[n]=name
  int32_t rc_ = 0;
  int32_t length_ = 1024;
  int32_t gap_ = 1;
  std::array<int32_t, kRecorderParameters> rp_{1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  int32_t launched_ = -1;  // the RR that launched the recording in the recorder
};

}  // namespace uprog::gold
