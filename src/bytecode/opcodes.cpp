// Name lookup for the assembler; everything else about opcodes is constexpr in opcodes.h.
#include "bytecode/opcodes.h"

namespace uprog::bytecode {

bool op_from_name(const char* name, uint32_t length, Op& out) {
  for (uint32_t i = 0; i < kOpCount; ++i) {
    const char* candidate = kOpInfo[i].name;
    uint32_t k = 0;
    while (k < length && candidate[k] != '\0' && candidate[k] == name[k]) ++k;
    if (k == length && candidate[k] == '\0') {
      out = static_cast<Op>(i);
      return true;
    }
  }
  return false;
}

}  // namespace uprog::bytecode
