// One CUP line as the loader has parsed and checked it: its keyword, its message, its effect on
// the expression stack and where control goes after it.
#pragma once
#include <cstdint>

#include "dialects/pup/keywords.h"
#include "dialects/pup/message.h"

namespace uprog::pup {

struct LineOp {
  const Keyword* key = nullptr;
  Message msg;
  const Keyword* name_key = nullptr;  // the parameter after `,` (APushParam, …)
  int pops = 0, pushes = 0;
  bool falls_through = true;
  uint32_t target = 0;  // a jump's line
  // Hand-written CUP whose line always finds too few entries (27) or would pass 50 (26): the
  // manual's run-time error when the line runs (the loader's depths prove it always does).
  int32_t fails = 0;
};

}  // namespace uprog::pup
