// Whole source lines per background slice: one program thread runs N lines each slice (Gold: a
// background pass), or, unlimited, until it waits, yields or ends (capped). Gold's schedule
// (manual 2.2).
#pragma once
#include <cstdint>

#include "dialect/scheduling/report.h"
#include "vm/machine.h"

namespace uprog::scheduling {

struct LineTiming {
  // Whole source lines per slice (0: no line limit, only the back-jump cap).
  uint32_t lines_per_cycle = 1;
  // Run until the program waits, yields or ends: only waits advance time (CI, benchmarks).
  bool unlimited = false;
  // The guard for `unlimited`: a slice stops after this many lines even without a wait, so a
  // busy loop cannot hang the simulation; it continues in the next slice.
  uint64_t unlimited_line_cap = 1'000'000;
  // Every slice also stops after this many jumps back, so that an image whose loop never ends
  // a line (hand-made) cannot stop the drive answering.
  uint64_t back_jump_cap = 1'000'000;
  // A background slice every this many µs, fixed; 0: the dialect's own pace (Gold: from TS,
  // manual 2.2; docs/dialects/gold-firmware.md).
  uint32_t background_us = 0;
};

class WholeLines {
 public:
  explicit WholeLines(LineTiming timing = {}) : timing_(timing) {}

  const LineTiming& timing() const { return timing_; }
  void set_timing(LineTiming timing) { timing_ = timing; }
  // What one slice may run.
  vm::Budget budget() const;

  // One background slice of `thread`: nothing unless it is running or waiting.
  Report slice(vm::Machine& machine, uint32_t thread) const;

 private:
  LineTiming timing_;
};

}  // namespace uprog::scheduling
