// What the VM needs from the world around it: drive commands and a clock. The controller
// implements it; the VM never sees a drive, a file or a socket.
#pragma once
#include <cstdint>

#include "support/value.h"

namespace uprog::vm {

// 0 when the command succeeded, otherwise the drive's (the dialect's) error code.
using CommandStatus = int32_t;
constexpr CommandStatus kCommandOk = 0;

class Host {
 public:
  // Read command `command` (a dialect-defined number) at `index`; `out` has the command's type.
  virtual CommandStatus read(uint32_t command, int32_t index, Value& out) = 0;
  // Write a value already converted to the command's type.
  virtual CommandStatus write(uint32_t command, int32_t index, Value value) = 0;
  // Run an action command (BG, ST, ...) with optional arguments.
  virtual CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                                uint32_t arg_count) = 0;
  // Virtual time in microseconds; wraps at 2^32.
  virtual uint32_t now_us() = 0;

 protected:
  ~Host() = default;
};

}  // namespace uprog::vm
