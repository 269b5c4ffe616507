// PDL's registered compile diagnostics (errors.def) and the one way the compiler makes them.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "support/diagnostic.h"

namespace uprog::pdl {

enum class Error {
#define PDL_ERROR(code, name, text) name = code,
#include "dialects/pdl/errors.def"
#undef PDL_ERROR
};

struct ErrorEntry {
  int code;
  std::string_view name;
  std::string_view text;
};

// Every registered code, in code order.
const ErrorEntry* all_errors(size_t& count);
std::string_view error_text(Error e);
// Codes 200 and above are warnings.
bool is_warning(Error e);
// "text: detail" (or the text alone), as a Diagnostic of scheme "pdl".
Diagnostic make_diagnostic(Error e, Location where, std::string_view detail = {});

}  // namespace uprog::pdl
