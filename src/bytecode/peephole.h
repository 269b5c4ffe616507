// The peephole pass: rewrites common instruction sequences of any dialect's code into the
// superinstructions of opcodes.def (fused compare-and-branch, local-and-constant arithmetic,
// end-of-line-and-jump), keeping every jump target, routine entry and line boundary.
#pragma once
#include "bytecode/image.h"

namespace uprog::bytecode {

struct PeepholeStats {
  uint32_t words_before = 0;
  uint32_t words_after = 0;
  uint32_t fused = 0;  // sequences replaced
};

// Leaves the image unchanged when its code does not decode (the verifier will say why) or
// carries line-end marks.
PeepholeStats optimize(Image& image);

}  // namespace uprog::bytecode
