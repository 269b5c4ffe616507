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
const char* run_error_name(RunError e);
// False when `code` is not a registered error.
bool run_error_from_code(uint32_t code, RunError& out);

}  // namespace uprog::vm
