// The compile-time pass over any dialect's base code: compare-and-jumps, line-end marks, dead code
// and jump threading (peephole.cpp), keeping every jump target, routine entry and line boundary.
// It makes base instructions only; fusion is the VM's, at load (vm/fused.def).
#pragma once
#include "bytecode/image.h"

namespace uprog::bytecode {

struct PeepholeStats {
  uint32_t words_before = 0;
  uint32_t words_after = 0;
  uint32_t fused = 0;  // sequences replaced by one base instruction
};

// Leaves the image unchanged when its code does not decode (the verifier will say why).
PeepholeStats optimize(Image& image);

}  // namespace uprog::bytecode
