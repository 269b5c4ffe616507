// The verifier: proves an image safe before the VM runs it. Every instruction decodes; every
// jump lands on an instruction; every constant, global, local and routine index is in range;
// the stack depth agrees where paths join and stays within the limit; no path falls off the end.
#pragma once
#include <cstddef>
#include <cstdint>

#include "bytecode/image_view.h"

namespace uprog::bytecode {

enum class VerifyError : uint8_t {
  Ok = 0,
  EmptyCode,
  BadOpcode,
  Truncated,     // an instruction's B word lies past the end
  BreakInImage,  // BREAK belongs to debuggers, never to an image
  BadConstant,
  BadGlobal,
  BadLocal,
  BadRoutine,
  BadTarget,   // a jump into the middle of an instruction or outside the code
  BadOperand,  // a count or unit out of its range
  BadEntry,    // a routine entry that is not an instruction
  StackUnderflow,
  StackOverflow,
  StackMismatch,  // two paths join with different depths
  FallsOffEnd,
  ReturnWithValues,  // RET with values left on the expression stack
  NoScratch,         // the caller's scratch memory is too small
  BadLineEnd,        // the line-end mark on an instruction that cannot carry it
};
const char* verify_error_text(VerifyError e);

struct VerifyLimits {
  uint32_t max_stack = 50;  // expression stack entries one frame may use
};

struct VerifyResult {
  VerifyError error = VerifyError::Ok;
  uint32_t pc = 0;         // where it was found
  uint32_t max_depth = 0;  // the deepest expression stack any frame reaches (when Ok)
  bool ok() const { return error == VerifyError::Ok; }
};

// The scratch memory verify() needs for this image, in bytes.
size_t verify_scratch_size(const ImageView& image);

// `scratch` must hold verify_scratch_size(image) bytes, aligned for uint32_t.
VerifyResult verify(const ImageView& image, const VerifyLimits& limits, void* scratch,
                    size_t scratch_size);

// The expression-stack depth on entry to the instruction at `pc` on the paths from routine
// `routine`'s entry (and the catch blocks they enter), as verify() proves it: where a debugger
// may move a thread of that routine without breaking what the VM relies on. False when no such
// path reaches `pc`, the routine's paths do not verify, or `scratch` is too small (as verify()).
bool stack_depth_at(const ImageView& image, const VerifyLimits& limits, uint32_t routine,
                    uint32_t pc, void* scratch, size_t scratch_size, uint32_t& depth);

}  // namespace uprog::bytecode
