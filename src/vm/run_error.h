// The run-time error enum, generated from run_errors.def, and its text.
#pragma once
#include <cstdint>

namespace uprog::vm {

enum class RunError : uint8_t {
#define RUN_ERROR(name, code, text) name = code,
#include "vm/run_errors.def"
#undef RUN_ERROR
};

const char* run_error_text(RunError e);

// The error's name as run_errors.def spells it, for tests and tools. Inline: the core's own code
// never asks for it, so a firmware that links the core does not carry the names.
inline const char* run_error_name(RunError e) {
  switch (e) {
#define RUN_ERROR(name, code, text) \
  case RunError::name:              \
    return #name;
#include "vm/run_errors.def"
#undef RUN_ERROR
  }
  return "Unknown";
}

// False when `code` is not a registered error.
bool run_error_from_code(uint32_t code, RunError& out);

}  // namespace uprog::vm
