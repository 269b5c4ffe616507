// Test support: assemble text, load it into a Machine with a scripted host, run it to the end.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "vm/machine.h"

namespace uprog::test {

// Command 1: ten read/write registers. Command 2: always refused with code 21.
// Command 3: an action that counts its runs, keeps its index and sums its arguments into
// register 0. Command 4: as 1 and 3 together, but every call ends the slice. Command 5: a
// counter of its reads, read-only: the n-th read (at any index) gives n.
// The first kKeptMessages messages are kept (without allocating: the VM's no-allocation test
// runs through this host), all are counted, each answered with message_status.
class ScriptedHost final : public vm::Host {
 public:
  static constexpr uint32_t kKeptMessages = 16;
  static constexpr uint32_t kKeptArgs = 16;
  struct Message {
    uint32_t thread = 0;
    uint32_t text = 0;
    uint32_t count = 0;  // arguments sent; the first kKeptArgs are kept
    int32_t args[kKeptArgs] = {};
    std::vector<int32_t> arguments() const {
      return std::vector<int32_t>(args, args + (count < kKeptArgs ? count : kKeptArgs));
    }
  };

  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override {
    if (command == 5) {
      out = Value::of_int(++counter_reads);
      return vm::kCommandOk;
    }
    if ((command != 1 && command != 4) || index < 0 || index >= 10) return command == 2 ? 21 : 22;
    out = registers[index];
    return done(command);
  }
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override {
    if ((command != 1 && command != 4) || index < 0 || index >= 10) return command == 2 ? 21 : 22;
    registers[index] = value;
    return done(command);
  }
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t n) override {
    if (command != 3 && command != 4) return 21;
    ++runs;
    action_index = index;
    for (uint32_t i = 0; i < n; ++i) registers[0].i += args[i].i;
    return done(command);
  }
  vm::CommandStatus message(uint32_t thread, uint32_t text, const Value* args,
                            uint32_t n) override {
    if (message_count < kKeptMessages) {
      Message& m = messages[message_count];
      m.thread = thread;
      m.text = text;
      m.count = n;
      for (uint32_t i = 0; i < n && i < kKeptArgs; ++i) m.args[i] = args[i].i;
    }
    ++message_count;
    return message_status;
  }
  uint32_t now_us() override { return clock_us; }

  Value registers[10] = {};
  int32_t counter_reads = 0;  // command 5
  int runs = 0;
  int32_t action_index = -1;
  Message messages[kKeptMessages];
  uint32_t message_count = 0;
  vm::CommandStatus message_status = vm::kCommandOk;
  uint32_t clock_us = 0;

 private:
  static vm::CommandStatus done(uint32_t command) {
    return command == 4 ? vm::kCommandEndSlice : vm::kCommandOk;
  }
};

struct LoadedProgram {
  bytecode::Image image;
  std::vector<uint8_t> bytes;
  std::vector<uint64_t> memory;
  ScriptedHost host;
  vm::Machine machine;
  vm::LoadStatus status;
  uint64_t slices = 0;  // run by run_to_end()

  // Assembles and loads; ADD_FAILURE on assembly errors.
  bool load(const std::string& text, vm::MachineConfig config = {}) {
    std::vector<Diagnostic> errors;
    if (!bytecode::assemble(text, "test.s", image, errors)) {
      ADD_FAILURE() << format_text(errors);
      return false;
    }
    bytes = bytecode::encode(image);
    bytecode::ImageView view;
    bytecode::load_image(bytes.data(), bytes.size(), view);
    memory.assign(vm::Machine::memory_needed(view, config) / 8 + 1, 0);
    status =
        machine.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, host);
    return status.ok();
  }

  // Runs thread 0 until it finishes or stops; waits advance the clock by 100 µs per slice.
  vm::SliceResult run_to_end(uint32_t thread = 0, uint64_t max_slices = 1000000) {
    vm::SliceResult r{};
    for (uint64_t i = 0; i < max_slices; ++i) {
      ++slices;
      r = machine.run_slice(thread, vm::Budget::unlimited());
      if (r.end == vm::SliceEnd::Waiting) host.clock_us += 100;
      if (r.end != vm::SliceEnd::Waiting && r.end != vm::SliceEnd::Yielded &&
          r.end != vm::SliceEnd::BudgetSpent)
        break;
    }
    return r;
  }

  Value global(const std::string& name, uint32_t element = 0) {
    Value v = Value::of_bits(0xDEADBEEF);
    const int g = image.find_global(name);
    EXPECT_GE(g, 0) << name;
    if (g >= 0) {
      EXPECT_TRUE(machine.read_global(static_cast<uint32_t>(g), element, v));
    }
    return v;
  }
};

}  // namespace uprog::test
