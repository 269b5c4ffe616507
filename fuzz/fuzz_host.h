// A fake vm::Host for the fuzz targets: deterministic answers, some commands refused, and a
// clock that moves on every call, so waits end and the refusal paths run.
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
  vm::CommandStatus execute(uint32_t command, int32_t, const Value*, uint32_t arg_count) override {
    ++now;
    return (command + arg_count) % 7 == 3 ? 19 : vm::kCommandOk;
  }
  uint32_t now_us() override { return now += 97; }

  uint32_t now = 0;
  ~FuzzHost() = default;
};

}  // namespace uprog::fuzz
