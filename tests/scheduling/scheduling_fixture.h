// Test support for the scheduling policies: a host that records what the programs write, in
// order, and a machine loaded from uprog assembly.
#pragma once
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "vm/machine.h"

namespace uprog::test {

// Command 1 at any index: a write appends the value to `trace`; a read gives register[index]
// (0..9). Command 2: an action that calls `on_action(code)` with its one argument (`PUSHI code;
// CMDRUN 2 1`): lock, unlock, charge, ... as the test decides.
class TraceHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override {
    if (command != 1 || index < 0 || index >= 10) return 22;
    out = registers[index];
    return vm::kCommandOk;
  }
  vm::CommandStatus write(uint32_t command, int32_t, Value value) override {
    if (command != 1) return 22;
    trace.push_back(value.i);
    return vm::kCommandOk;
  }
  vm::CommandStatus execute(uint32_t command, int32_t, const Value* args, uint32_t n) override {
    if (command != 2 || n != 1) return 21;
    if (on_action) on_action(args[0].i);
    return vm::kCommandOk;
  }
  uint32_t now_us() override { return clock_us; }

  std::vector<int32_t> trace;
  Value registers[10] = {};
  std::function<void(int32_t)> on_action;
  uint32_t clock_us = 0;
};

struct Drive {
  bytecode::Image image;
  std::vector<uint8_t> bytes;
  std::vector<uint64_t> memory;
  TraceHost host;
  vm::Machine machine;

  // Assembles and loads; ADD_FAILURE on assembly or load errors.
  bool load(const std::string& text, uint32_t threads) {
    std::vector<Diagnostic> errors;
    if (!bytecode::assemble(text, "test.s", image, errors)) {
      ADD_FAILURE() << format_text(errors);
      return false;
    }
    bytes = bytecode::encode(image);
    bytecode::ImageView view;
    bytecode::load_image(bytes.data(), bytes.size(), view);
    vm::MachineConfig config;
    config.threads = threads;
    memory.assign(vm::Machine::memory_needed(view, config) / 8 + 1, 0);
    const vm::LoadStatus status =
        machine.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, host);
    EXPECT_TRUE(status.ok()) << "load " << static_cast<int>(status.load) << ", verify "
                             << static_cast<int>(status.verify) << " at " << status.pc;
    return status.ok();
  }

  uint32_t routine(const std::string& name) const {
    const int r = image.find_routine(name);
    EXPECT_GE(r, 0) << name;
    return static_cast<uint32_t>(r);
  }
  void start(uint32_t thread, const std::string& name) {
    ASSERT_EQ(machine.start(thread, routine(name)), vm::RunError::None) << name;
  }
  int32_t global(const std::string& name) const {
    const int g = image.find_global(name);
    EXPECT_GE(g, 0) << name;
    Value v = Value::of_int(-1);
    machine.read_global(static_cast<uint32_t>(g), 0, v);
    return v.i;
  }
  // The trace since the last call.
  std::vector<int32_t> take_trace() {
    std::vector<int32_t> t;
    t.swap(host.trace);
    return t;
  }
};

// One line each: write `value` to the trace; run action `code`; sleep `ms` (a timed wait).
inline std::string write_line(int value) {
  return "  PUSHI " + std::to_string(value) + "\n  CMDSET 1 0\n  EOL\n";
}
inline std::string action_line(int code) {
  return "  PUSHI " + std::to_string(code) + "\n  CMDRUN 2 1\n  EOL\n";
}
inline std::string sleep_line(int ms) {
  return "  PUSHI " + std::to_string(ms) + "\n  WAIT 1000\n  EOL\n";
}
inline std::string routine_header(const std::string& name) {
  return ".routine task \"" + name + "\" in=0 out=0 entry=" + name + "\n" + name + ":\n";
}
// Writes `value` in every line from here on: a label and a line that jumps back to it.
inline std::string write_forever(const std::string& label, int value) {
  return label + ":\n  PUSHI " + std::to_string(value) + "\n  CMDSET 1 0\n  JMP.eol " + label +
         "\n";
}

// A task that writes `id` in every line, forever: each line is `PUSHI id; CMDSET 1 0; EOL`.
inline std::string forever_writer(const std::string& name, int id) {
  return ".routine task \"" + name + "\" in=0 out=0 entry=" + name + "\n" + write_forever(name, id);
}

// A task of `lines` lines that writes `id` in each, then ends (its end is a bare RET).
inline std::string counted_writer(const std::string& name, int id, int lines) {
  std::string s = routine_header(name);
  for (int i = 0; i < lines; ++i) s += write_line(id);
  return s + "  RET\n";
}

}  // namespace uprog::test
