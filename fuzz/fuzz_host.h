// A fake vm::Host for the fuzz targets: deterministic answers, some commands refused, some
// ending the slice, messages taken, and a clock that moves on every call, so waits end and the
// refusal and end-of-slice paths run.
#pragma once
#include <cstdint>

#include "vm/host.h"

namespace uprog::fuzz {

class FuzzHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override {
    ++now;
    out = Value::of_bits(command * 2654435761u ^ static_cast<uint32_t>(index));
    return command % 11 == 7 ? 21 : vm::kCommandOk;
  }
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override {
    ++now;
    return (command + static_cast<uint32_t>(index) + value.bits) % 13 == 5 ? 33 : vm::kCommandOk;
  }
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value*,
                            uint32_t arg_count) override {
    ++now;
    if ((command + arg_count) % 7 == 3) return 19;
    return static_cast<uint32_t>(index) % 5 == 4 ? vm::kCommandEndSlice : vm::kCommandOk;
  }
  vm::CommandStatus message(uint32_t, uint32_t text, const Value* args, uint32_t count) override {
    ++now;
    for (uint32_t i = 0; i < count; ++i) checksum ^= args[i].bits;  // reads every argument
    return text % 3 == 1 ? 27 : text % 3 == 2 ? vm::kCommandEndSlice : vm::kCommandOk;
  }
  uint32_t now_us() override { return now += 97; }

  uint32_t now = 0;
  uint32_t checksum = 0;
  ~FuzzHost() = default;
};

}  // namespace uprog::fuzz
