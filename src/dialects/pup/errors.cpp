// The PUP diagnostics table and make_error (errors.h).
#include "dialects/pup/errors.h"

namespace uprog::pup {
namespace {

constexpr dialect::ErrorInfo kTable[] = {
#define PUP_ERROR(code, name, text) {code, #name, text},
#include "dialects/pup/pup_errors.def"
#undef PUP_ERROR
};

constexpr dialect::ErrorInfo kInterpreterErrors[] = {
#define EC(code, name, text) {code, #name, text},
#include "dialects/pup/interpreter_errors.def"
#undef EC
};

}  // namespace

std::span<const dialect::ErrorInfo> diagnostic_table() { return kTable; }
std::span<const dialect::ErrorInfo> interpreter_error_table() { return kInterpreterErrors; }

Diagnostic make_error(Error e, Location where, const std::string& detail) {
  Diagnostic d;
  d.scheme = "pup";
  d.code = static_cast<int>(e);
  for (const dialect::ErrorInfo& info : kTable) {
    if (info.code == d.code) d.message = std::string(info.text);
  }
  if (!detail.empty()) d.message += ": " + detail;
  d.where = std::move(where);
  return d;
}

}  // namespace uprog::pup
