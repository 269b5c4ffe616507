// Shared by the fuzz targets: load image bytes into a Machine (with a memory cap, as a drive
// has) and, if it loads, run every routine for a bounded budget, with an event entered midway and
// the thread halted and moved.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_host.h"
#include "vm/machine.h"

namespace uprog::fuzz {

constexpr size_t kMaxMachineMemory = 32u << 20;  // bytes: a larger image is "no memory"
constexpr uint32_t kMaxRoutinesRun = 32;
constexpr uint32_t kSlicesPerRoutine = 8;
constexpr uint64_t kInstructionsPerSlice = 2000;
constexpr uint64_t kLinesPerSlice = 200;

// Returns the load status; runs the routines when it is ok.
inline vm::LoadStatus load_and_run(const uint8_t* bytes, size_t size) {
  vm::MachineConfig config;
  config.threads = 2;
  bytecode::ImageView view;
  if (bytecode::load_image(bytes, size, view) != bytecode::LoadError::Ok) {
    // Still through Machine::load, which must refuse it the same way.
    FuzzHost host;
    vm::Machine machine;
    uint64_t memory[64];
    return machine.load(bytes, size, config, memory, sizeof memory, host);
  }
  const size_t need = vm::Machine::memory_needed(view, config);
  if (need > kMaxMachineMemory)
    return vm::LoadStatus{bytecode::LoadError::Ok, bytecode::VerifyError::Ok, 0, true};
  std::vector<uint64_t> memory(need / 8 + 1);
  FuzzHost host;
  vm::Machine machine;
  const vm::LoadStatus status =
      machine.load(bytes, size, config, memory.data(), memory.size() * 8, host);
  if (!status.ok()) return status;

  const uint32_t routines = view.routines.size();
  Value args[16] = {};
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(view) / 4 + 1);
  for (uint32_t r = 0; r < routines && r < kMaxRoutinesRun; ++r) {
    const uint32_t inputs = view.routines[r].inputs;
    machine.start(0, r, args, inputs <= 16 ? inputs : 0);
    for (uint32_t s = 0; s < kSlicesPerRoutine; ++s) {
      if (s == 2) machine.interrupt(0, (r + 1) % routines);
      if (s == 4) {
        // Halted and moved to a code word the VM must refuse unless it is safe to go on from.
        machine.halt(0);
        const uint32_t pc = (machine.pc(0) * 7u + r) % static_cast<uint32_t>(view.code.size());
        machine.move_pc(0, pc, scratch.data(), scratch.size() * 4);
        (void)machine.operand_stack(0);
      }
      if (s == 5) machine.resume(0);
      // Slice 6 counts lines and back jumps, not instructions, as a dialect's scheduler does:
      // the fused copies (JLINES) run only in such slices.
      const vm::Budget budget = s == 6 ? vm::Budget{0, kLinesPerSlice, kInstructionsPerSlice}
                                       : vm::Budget::of_instructions(kInstructionsPerSlice);
      const vm::SliceResult res = machine.run_slice(0, budget);
      if (res.end == vm::SliceEnd::Finished || res.end == vm::SliceEnd::Error ||
          res.end == vm::SliceEnd::NotRunning)
        break;
    }
    // The debugger's view of whatever is left.
    for (uint32_t d = 0; d < machine.frame_count(0); ++d) {
      const vm::FrameInfo f = machine.frame(0, d);
      Value v;
      machine.read_local(0, d, 0, v);
      (void)f;
    }
    machine.kill(0);
  }
  // A breakpoint on the first routine's entry, hit and resumed.
  if (routines > 0 && machine.set_breakpoint(view.routines[0].entry)) {
    machine.start(1, 0, args, view.routines[0].inputs <= 16 ? view.routines[0].inputs : 0);
    machine.run_slice(1, vm::Budget::of_instructions(kInstructionsPerSlice));
    machine.resume(1);
    machine.run_slice(1, vm::Budget::of_instructions(kInstructionsPerSlice));
    machine.clear_breakpoint(view.routines[0].entry);
  }
  return status;
}

}  // namespace uprog::fuzz
