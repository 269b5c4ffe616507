// Names and texts of the run-time errors.
#include "vm/run_error.h"

namespace uprog::vm {

const char* run_error_text(RunError e) {
  switch (e) {
#define RUN_ERROR(name, code, text) \
  case RunError::name:              \
    return text;
#include "vm/run_errors.def"
#undef RUN_ERROR
  }
  return "unknown run-time error";
}

bool run_error_from_code(uint32_t code, RunError& out) {
  switch (code) {
#define RUN_ERROR(name, code, text) \
  case code:                        \
    out = RunError::name;           \
    return true;
#include "vm/run_errors.def"
#undef RUN_ERROR
  }
  return false;
}

}  // namespace uprog::vm
