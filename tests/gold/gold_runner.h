// Test support: compile Gold source, load the image into a Machine with a TestHost, run a
// routine to its end, read globals by name.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dialects/gold/commands.h"
#include "dialects/gold/compile.h"
#include "test_host.h"
#include "vm/machine.h"

namespace uprog::gold_test {

struct GoldRun {
  bytecode::Image image;
  std::vector<uint8_t> bytes;
  std::vector<uint64_t> memory;
  TestHost host;
  vm::Machine machine;
  vm::SliceEnd end = vm::SliceEnd::NotRunning;
  uint64_t slices = 0;

  bool compile(const std::string& source) {
    gold::CompileResult r = gold::compile(SourceFile{"test.ehl", source});
    if (!r.ok()) {
      ADD_FAILURE() << format_text(r.diagnostics);
      return false;
    }
    return load(std::move(r.image));
  }
  bool load(bytecode::Image img) {
    image = std::move(img);
    bytes = bytecode::encode(image);
    bytecode::ImageView view;
    if (bytecode::load_image(bytes.data(), bytes.size(), view) != bytecode::LoadError::Ok) {
      ADD_FAILURE() << "image does not load";
      return false;
    }
    vm::MachineConfig config;
    memory.assign(vm::Machine::memory_needed(view, config) / 8 + 1, 0);
    const vm::LoadStatus st =
        machine.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, host);
    if (!st.ok())
      ADD_FAILURE() << "the VM refuses the image: verify error " << static_cast<int>(st.verify)
                    << " at pc " << st.pc;
    return st.ok();
  }
  // Runs `routine` on thread 0 until it ends; each slice moves the clock by `step_us`.
  vm::SliceEnd run(const std::string& routine, uint32_t step_us = 1000,
                   uint64_t max_slices = 100000) {
    const int r = image.find_routine(routine);
    EXPECT_GE(r, 0) << "no routine " << routine;
    if (r < 0) return vm::SliceEnd::NotRunning;
    machine.start(0, static_cast<uint32_t>(r));
    for (slices = 0; slices < max_slices; ++slices) {
      end = machine.run_slice(0, vm::Budget::of_instructions(100000)).end;
      if (end == vm::SliceEnd::Finished || end == vm::SliceEnd::Error) return end;
      host.now += step_us;
    }
    return end;
  }
  Value global(const std::string& name, uint32_t element = 0) const {
    Value v = Value::of_int(0);
    const int g = image.find_global(name);
    EXPECT_GE(g, 0) << "no global " << name;
    if (g >= 0) machine.read_global(static_cast<uint32_t>(g), element, v);
    return v;
  }
  int32_t i(const std::string& name, uint32_t element = 0) const { return global(name, element).i; }
  float f(const std::string& name, uint32_t element = 0) const { return global(name, element).f; }
  Value command(const char* name, int32_t index = 0) {
    const gold::CommandInfo* c = gold::find_command(name);
    auto it = host.values.find({c->id, index});
    return it == host.values.end() ? Value::of_int(0) : it->second;
  }
};

}  // namespace uprog::gold_test
