// The registry: every dialect of this build, one line each in registry.def (or, for a test's
// registry, the list UPROG_REGISTRY_DEF names).
#include "dialects/registry.h"

#include <cctype>

#ifndef UPROG_REGISTRY_DEF
#define UPROG_REGISTRY_DEF "dialects/registry.def"
#endif

// Each dialect's entry, as its dialects/NAME/dialect.h declares it.
#define UPROG_DIALECT(NAME)                   \
  namespace uprog::NAME {                     \
  const ::uprog::dialect::Dialect& dialect(); \
  }
#include UPROG_REGISTRY_DEF
#undef UPROG_DIALECT

namespace uprog::dialects {
namespace {

const dialect::Dialect* const kDialects[] = {
#define UPROG_DIALECT(NAME) &::uprog::NAME::dialect(),
#include UPROG_REGISTRY_DEF
#undef UPROG_DIALECT
};

bool ends_with_ignoring_case(std::string_view text, std::string_view suffix) {
  if (text.size() < suffix.size()) return false;
  text.remove_prefix(text.size() - suffix.size());
  for (size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(suffix[i]))) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::span<const dialect::Dialect* const> all() { return kDialects; }

const dialect::Dialect* find(std::string_view name) {
  for (const dialect::Dialect* d : kDialects) {
    if (d->name() == name) return d;
  }
  return nullptr;
}

const dialect::Dialect* for_file(std::string_view path) {
  for (const dialect::Dialect* d : kDialects) {
    for (std::string_view extension : d->source_extensions()) {
      if (ends_with_ignoring_case(path, extension)) return d;
    }
    if (ends_with_ignoring_case(path, d->stored_extension())) return d;
  }
  return nullptr;
}

const dialect::Dialect& default_dialect() { return *kDialects[0]; }

}  // namespace uprog::dialects
