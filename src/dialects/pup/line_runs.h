// Fused copies of CUP code. From a line on, the lines that cannot fail, wait, call or reach the
// firmware (AGenData, constants, the VM's own AMath and ACompare) are compiled again as one
// piece: every path through them to the first line that is not such a line, or back to an
// earlier one, is a path of the copy, which leaves by a JMPLN that counts the lines the path ran
// (a jump back to the copy's own first line goes on into the loop's next turn instead, while a
// whole turn more fits in a path).
// The peephole pass fuses the piece, so a path takes fewer instructions than it has lines. The
// loader puts a JLINES before the line: a slice that may run the longest path at once takes the
// copy, every other slice (the drive's one line a cycle, stepping, a breakpoint set) the lines
// one by one.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "bytecode/image.h"
#include "dialects/pup/line_op.h"

namespace uprog::pup {

struct LineRun {
  uint32_t first = 0;          // the CUP line whose JLINES enters the copy
  uint32_t most = 0;           // the most lines a path through the copy runs
  std::vector<uint32_t> code;  // the copy; its JMPLNs target kRunExit + a CUP line
  // The CUP line of its start and of each instruction that may fail (an index out of its
  // window): code word and line, in code order.
  std::vector<std::pair<uint32_t, uint32_t>> lines;
};
constexpr uint32_t kRunExit = 1u << 22;

// The copies worth having, in line order. `ops` and `depth` are by CUP line from 1 (depth -1:
// not reached); `entered[l]`: control may arrive at line l other than from line l - 1. Adds to
// `image` the constants the copies use and a global "AGenData[n]" for each element they name,
// which bind_gen_data places on element n of the general data.
std::vector<LineRun> fuse_line_runs(const std::vector<LineOp>& ops,
                                    const std::vector<int32_t>& depth,
                                    const std::vector<bool>& entered, bytecode::Image& image);

}  // namespace uprog::pup
