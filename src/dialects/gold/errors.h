// The Gold compiler's error codes (generated from gold_errors.def) and the one place that turns
// a code and a place into a Diagnostic, so every message reads "<text> [gold <code>]".
#pragma once
#include <string>
#include <string_view>

#include "support/diagnostic.h"

namespace uprog::gold {

enum class Error : int {
#define GOLD_ERROR(code, name, text, illustrated) name = code,
#include "dialects/gold/gold_errors.def"
#undef GOLD_ERROR
};

struct ErrorInfo {
  int code;
  const char* name;
  const char* text;
  bool illustrated;  // the manual shows an example that produces it
};

// Every registered code, in code order.
const ErrorInfo* all_errors(size_t& count);
const char* error_text(Error e);
const char* error_name(Error e);

Diagnostic make_error(Error e, Location where, std::string detail = {});
// The manual's text and the name the error is about: "No such variable 'spd'" (no name: the
// text alone). A name longer than a program may hold is cut.
Diagnostic make_error_about(Error e, Location where, std::string_view name);

}  // namespace uprog::gold
