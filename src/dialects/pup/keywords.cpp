// The keyword table (keywords.def) and its case-insensitive lookup.
#include "dialects/pup/keywords.h"

#include <cctype>

namespace uprog::pup {
namespace {

constexpr uint8_t C = kOverLine, P = kInProgram, U = kNeedsProgram, M = kNotInMotion;

constexpr Keyword kKeywords[] = {
#define PUP_KEYWORD(id, name, kind, attrs, index_min, index_max, arg)        \
  {KeywordId::id, name,      KeywordKind::kind, static_cast<uint8_t>(attrs), \
   index_min,     index_max, ArgKind::arg},
#include "dialects/pup/keywords.def"
#undef PUP_KEYWORD
};

bool same_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

}  // namespace

const Keyword* find_keyword(std::string_view name) {
  for (const Keyword& k : kKeywords) {
    if (same_ignoring_case(k.name, name)) return &k;
  }
  return nullptr;
}

const Keyword& keyword(KeywordId id) { return kKeywords[static_cast<size_t>(id)]; }

}  // namespace uprog::pup
