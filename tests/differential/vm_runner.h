// Test support for the differential tests: load an image into a Machine with a Host that has
// no drive, run routine 0 to its end, and read globals.
#pragma once
#include <cstdint>
#include <vector>

#include "bytecode/image.h"
#include "vm/machine.h"

namespace uprog::differential {

class NoDriveHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t, int32_t, Value& out) override {
    out = Value::of_int(0);
    return vm::kCommandOk;
  }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return vm::kCommandOk; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override {
    return vm::kCommandOk;
  }
  uint32_t now_us() override { return 0; }
  ~NoDriveHost() = default;
};

struct VmRun {
  bool loaded = false;
  vm::SliceEnd end = vm::SliceEnd::NotRunning;
  vm::RunError error = vm::RunError::None;
  std::vector<uint8_t> bytes;
  std::vector<uint64_t> memory;
  NoDriveHost host;
  vm::Machine machine;

  // Loads `image` and runs its routine 0 to the end.
  void run(const bytecode::Image& image) {
    bytes = bytecode::encode(image);
    bytecode::ImageView view;
    if (bytecode::load_image(bytes.data(), bytes.size(), view) != bytecode::LoadError::Ok) return;
    vm::MachineConfig config;
    config.threads = 1;
    memory.assign(vm::Machine::memory_needed(view, config) / 8 + 1, 0);
    loaded =
        machine.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, host)
            .ok();
    if (!loaded) return;
    machine.start(0, 0);
    end = machine.run_slice(0, vm::Budget::of_instructions(1000000)).end;
    error = machine.last_error(0);
  }
  Value global(uint32_t g) const {
    Value v = Value::of_int(0);
    machine.read_global(g, 0, v);
    return v;
  }
};

}  // namespace uprog::differential
