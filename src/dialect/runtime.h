// What the controller lends a dialect's firmware: the axes, the drive's flash, the clock, the log
// and the channel for unsolicited output. The firmware owns its program and its machine; the
// controller owns time, the axes and the storage, and names no dialect.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "drive/parameters.h"

namespace uprog::drive {
class Axis;
}

namespace uprog::dialect {

// The drive's non-volatile memory: named records ("program.upi", "parameters.txt"), each
// replaced atomically, so that a kill at any moment leaves the old record or the new one. Without
// a state directory the records live in memory.
class Flash {
 public:
  // nullopt when the record does not exist or cannot be read (`error` says which, "" for none).
  virtual std::optional<std::vector<uint8_t>> read(std::string_view name, std::string* error) = 0;
  virtual bool write(std::string_view name, std::span<const uint8_t> bytes, std::string* error) = 0;
  // Where a record lives, for messages ("state/program.upi", or "program.upi (in memory)").
  virtual std::string where(std::string_view name) const = 0;

 protected:
  ~Flash() = default;
};

class Runtime {
 public:
  virtual std::size_t axis_count() const = 0;
  virtual drive::Axis& axis(std::size_t index = 0) = 0;
  virtual Flash& flash() = 0;
  // Virtual time since power-up.
  virtual uint64_t now_ns() const = 0;
  // Lets virtual time pass: what a host line costs the drive's background loop.
  virtual void advance_ns(uint64_t ns) = 0;
  virtual void log(std::string text) = 0;
  // Text the program or the firmware sends on its own; it reaches every connected host, the
  // output of `uprog run` and transcripts' `output` lines.
  virtual void output(std::string_view text) = 0;
  // Starts the drive again as at power-up (RS, COLDSTART): fresh axes with the saved parameters,
  // then the firmware's boot(). Not from inside the program's machine.
  virtual void reboot() = 0;
  // The first axis's parameters into the flash (SV, SAVE), and what was saved (LD, LOAD); the
  // firmware applies them itself, as its drive's rules allow.
  virtual bool save_axis_parameters(std::string* error) = 0;
  virtual std::optional<drive::Parameters> saved_axis_parameters(std::string* error) = 0;

 protected:
  ~Runtime() = default;
};

}  // namespace uprog::dialect
