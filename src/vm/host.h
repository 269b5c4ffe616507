// What the VM needs from the world around it: drive commands, messages and a clock. The
// controller implements it; the VM never sees a drive, a file or a socket.
#pragma once
#include <cstdint>

#include "support/value.h"

namespace uprog::vm {

// 0 when the command succeeded, otherwise the drive's (the dialect's) error code, which is
// positive: the VM stops the thread with CommandRefused and keeps the code as error_detail().
// Negative values are this contract's own.
using CommandStatus = int32_t;
constexpr CommandStatus kCommandOk = 0;
// Done, and the slice ends after this instruction, as at YIELD (SliceEnd::Yielded): a call
// that costs the rest of the thread's turn (Akribis' one line per cycle, ST's XREAD).
constexpr CommandStatus kCommandEndSlice = -1;
// The host offers no such service (what message() answers unless a host shows messages).
constexpr CommandStatus kCommandUnsupported = -2;

class Host {
 public:
  // Read command `command` (a dialect-defined number) at `index`; `out` has the command's type.
  virtual CommandStatus read(uint32_t command, int32_t index, Value& out) = 0;
  // Write a value already converted to the command's type.
  virtual CommandStatus write(uint32_t command, int32_t index, Value value) = 0;
  // Run an action command (BG, ST, ...) with optional arguments.
  virtual CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                                uint32_t arg_count) = 0;
  // Sends text `text` of the image (ImageView::text) with `count` raw argument words, from
  // `thread`: what a program prints (PDL's printl, ST's PRINTF). The host formats it
  // (support/format_message.h); the VM does not.
  virtual CommandStatus message(uint32_t thread, uint32_t text, const Value* args, uint32_t count) {
    (void)thread, (void)text, (void)args, (void)count;
    return kCommandUnsupported;
  }
  // Virtual time in microseconds; wraps at 2^32.
  virtual uint32_t now_us() = 0;

 protected:
  ~Host() = default;
};

}  // namespace uprog::vm
