// Fused copies of runs of CUP lines. A run is a sequence of lines that cannot fail, wait, call
// or reach the firmware (AGenData, constants, the VM's own AMath and ACompare), ending at its
// first jump. Compiled again as one piece by the peephole pass, its copy takes fewer
// instructions than the run has lines; the loader puts a JLINES before the run's first line, so
// that a slice which may run the whole run at once takes the copy, and every other slice (the
// drive's one line a cycle, stepping, a breakpoint set) the lines one by one.
#pragma once
#include <cstdint>
#include <vector>

#include "bytecode/image.h"
#include "dialects/pup/line_op.h"

namespace uprog::pup {

struct LineRun {
  uint32_t first = 0, last = 0;  // its CUP lines
  uint32_t counted = 0;          // the lines JLINES counts; the copy ends the others itself
  std::vector<uint32_t> code;    // the copy; a jump out of it targets kRunExit + a CUP line
};
constexpr uint32_t kRunExit = 1u << 22;

// The runs worth a copy, in line order. `ops` and `depth` are by CUP line from 1 (depth -1: not
// reached); `entered[l]`: control may arrive at line l other than from line l - 1. Adds to
// `image` the constants the copies use and a global "AGenData[n]" for each element they name,
// which bind_gen_data places on element n of the general data.
std::vector<LineRun> fuse_line_runs(const std::vector<LineOp>& ops, const std::vector<int32_t>& depth,
                                    const std::vector<bool>& entered, bytecode::Image& image);

}  // namespace uprog::pup
