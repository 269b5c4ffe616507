// The table behind errors.h.
#include "dialects/pdl/errors.h"

namespace uprog::pdl {
namespace {

constexpr ErrorEntry kErrors[] = {
#define PDL_ERROR(code, name, text) {code, #name, text},
#include "dialects/pdl/errors.def"
#undef PDL_ERROR
};

}  // namespace

const ErrorEntry* all_errors(size_t& count) {
  count = sizeof(kErrors) / sizeof(kErrors[0]);
  return kErrors;
}

std::string_view error_text(Error e) {
  for (const ErrorEntry& entry : kErrors)
    if (entry.code == static_cast<int>(e)) return entry.text;
  return "error";
}

bool is_warning(Error e) { return static_cast<int>(e) >= 200; }

Diagnostic make_diagnostic(Error e, Location where, std::string_view detail) {
  Diagnostic d;
  d.severity = is_warning(e) ? Severity::Warning : Severity::Error;
  d.scheme = "pdl";
  d.code = static_cast<int>(e);
  d.message = std::string(error_text(e));
  if (!detail.empty()) d.message += ": " + std::string(detail);
  d.where = std::move(where);
  return d;
}

}  // namespace uprog::pdl
