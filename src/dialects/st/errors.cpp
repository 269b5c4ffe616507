// The ST error table and the Diagnostic maker (errors.h).
#include "dialects/st/errors.h"

namespace uprog::st {
namespace {

constexpr ErrorInfo kErrors[] = {
#define ST_ERROR(code, name, text) {code, #name, text},
#include "dialects/st/st_errors.def"
#undef ST_ERROR
};

}  // namespace

const ErrorInfo* all_errors(size_t& count) {
  count = sizeof kErrors / sizeof kErrors[0];
  return kErrors;
}

const char* error_text(Error e) {
  for (const ErrorInfo& info : kErrors)
    if (info.code == static_cast<int>(e)) return info.text;
  return "error";
}

Diagnostic make_error(Error e, Location where, const std::string& detail) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.scheme = kScheme;
  d.code = static_cast<int>(e);
  d.message = error_text(e);
  if (!detail.empty()) d.message += ": " + detail;
  d.where = std::move(where);
  return d;
}

}  // namespace uprog::st
