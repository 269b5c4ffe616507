// The registered interpreter errors' texts (interpreter_errors.def).
#include "dialects/gold/interpreter_errors.h"

namespace uprog::gold {

const char* interpreter_error_text(int32_t code) {
  switch (code) {
#define EC(value, name, text) \
  case value:                 \
    return text;
#include "dialects/gold/interpreter_errors.def"
#undef EC
    default:
      return nullptr;
  }
}

}  // namespace uprog::gold
