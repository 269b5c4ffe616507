// The registered Gold error list, expanded from gold_errors.def.
#include "dialects/gold/errors.h"

namespace uprog::gold {

namespace {
constexpr ErrorInfo kErrors[] = {
#define GOLD_ERROR(code, name, text, illustrated) {code, #name, text, illustrated != 0},
#include "dialects/gold/gold_errors.def"
#undef GOLD_ERROR
};
constexpr size_t kErrorCount = sizeof(kErrors) / sizeof(kErrors[0]);

const ErrorInfo* find(Error e) {
  for (const ErrorInfo& info : kErrors)
    if (info.code == static_cast<int>(e)) return &info;
  return nullptr;
}
}  // namespace

const ErrorInfo* all_errors(size_t& count) {
  count = kErrorCount;
  return kErrors;
}

const char* error_text(Error e) {
  const ErrorInfo* info = find(e);
  return info ? info->text : "Unknown error";
}

const char* error_name(Error e) {
  const ErrorInfo* info = find(e);
  return info ? info->name : "UnknownError";
}

Diagnostic make_error(Error e, Location where, std::string detail) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.scheme = "gold";
  d.code = static_cast<int>(e);
  d.message = error_text(e);
  d.where = std::move(where);
  // The message stays the manual's text; what is specific to this place goes into a note.
  if (!detail.empty()) d.notes.push_back({d.where, std::move(detail)});
  return d;
}

Diagnostic make_error_about(Error e, Location where, std::string_view name) {
  // Longer than any name the compiler accepts (12, error 11), short enough for one line.
  constexpr size_t kMaxQuotedName = 40;
  Diagnostic d = make_error(e, std::move(where));
  if (name.empty()) return d;
  d.message += " '";
  d.message += name.substr(0, kMaxQuotedName);
  d.message += name.size() > kMaxQuotedName ? "...'" : "'";
  return d;
}

}  // namespace uprog::gold
