// The ST compiler's error codes (st_errors.def) and the one place that makes a Diagnostic of a
// code and a place, so every message reads "<text> [st <code>]".
#pragma once
#include <cstddef>
#include <string>

#include "support/diagnostic.h"

namespace uprog::st {

enum class Error : int {
#define ST_ERROR(code, name, text) name = code,
#include "dialects/st/st_errors.def"
#undef ST_ERROR
};

struct ErrorInfo {
  int code;
  const char* name;
  const char* text;
};

// Every registered code, in code order.
const ErrorInfo* all_errors(size_t& count);
const char* error_text(Error e);

constexpr const char* kScheme = "st";
// A compile stops collecting after this many errors and adds TooManyErrors.
constexpr size_t kMaxErrors = 30;

// "<text>" or "<text>: <detail>".
Diagnostic make_error(Error e, Location where, const std::string& detail = {});

}  // namespace uprog::st
