// The PUP compiler's registered diagnostics (pup_errors.def) and the one constructor of them,
// so every message reads "<text>: <detail> [pup N]"; the command line's error codes.
#pragma once
#include <span>
#include <string>

#include "dialect/dialect.h"
#include "support/diagnostic.h"

namespace uprog::pup {

enum class Error : int {
#define PUP_ERROR(code, name, text) name = code,
#include "dialects/pup/pup_errors.def"
#undef PUP_ERROR
};

std::span<const dialect::ErrorInfo> diagnostic_table();
// The command line's error codes (interpreter_errors.def), what `?code` answers carry.
std::span<const dialect::ErrorInfo> interpreter_error_table();
Diagnostic make_error(Error e, Location where, const std::string& detail = {});

}  // namespace uprog::pup
