// Keyword and auto-routine name tables.
#include "dialects/gold/keywords.h"

#include <array>

namespace uprog::gold {

Keyword keyword_of(std::string_view word) {
  struct Entry {
    std::string_view text;
    Keyword kw;
  };
  // Sorted by first letter; kFirst[c - 'a'] is where that letter's words begin.
  static constexpr std::array<Entry, 24> kWords = {{
      {"break", Keyword::Break},
      {"case", Keyword::Case},
      {"catch", Keyword::Catch},
      {"continue", Keyword::Continue},
      {"else", Keyword::Else},
      {"elseif", Keyword::Elseif},
      {"end", Keyword::End},
      {"exit", Keyword::Exit},
      {"float", Keyword::Float},
      {"for", Keyword::For},
      {"function", Keyword::Function},
      {"global", Keyword::Global},
      {"goto", Keyword::Goto},
      {"if", Keyword::If},
      {"int", Keyword::Int},
      {"nargout", Keyword::Nargout},
      {"otherwise", Keyword::Otherwise},
      {"reset", Keyword::Reset},
      {"return", Keyword::Return},
      {"switch", Keyword::Switch},
      {"try", Keyword::Try},
      {"until", Keyword::Until},
      {"wait", Keyword::Wait},
      {"while", Keyword::While},
  }};
  static constexpr auto kFirst = [] {
    std::array<uint8_t, 27> first{};
    size_t k = 0;
    for (size_t c = 0; c < 26; ++c) {
      first[c] = static_cast<uint8_t>(k);
      while (k < kWords.size() && static_cast<size_t>(kWords[k].text[0] - 'a') == c) ++k;
    }
    first[26] = static_cast<uint8_t>(kWords.size());
    return first;
  }();
  // Most names are no keyword: the length and the first letter decide that without a copy.
  if (word.size() < 2 || word.size() > 9) return Keyword::None;
  const char c0 = static_cast<char>(word[0] | 0x20);
  if (c0 < 'a' || c0 > 'z') return Keyword::None;
  const size_t b = kFirst[static_cast<size_t>(c0 - 'a')];
  const size_t e = kFirst[static_cast<size_t>(c0 - 'a') + 1];
  for (size_t k = b; k < e; ++k) {
    const std::string_view t = kWords[k].text;
    if (t.size() != word.size()) continue;
    size_t i = 1;
    while (i < t.size()) {
      const char c = word[i];
      const char lower = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;  // ASCII only
      if (lower != t[i]) break;
      ++i;
    }
    if (i == t.size()) return kWords[k].kw;
  }
  return Keyword::None;
}

const AutoRoutineName* find_auto_routine(std::string_view name) {
  static constexpr std::array<AutoRoutineName, 16> kNames = {{
      {"AUTOEXEC", 0},
      {"AUTO_ER", 1},
      {"AUTO_STOP", 2},
      {"AUTO_BG", 3},
      {"AUTO_RLS", 4},
      {"AUTO_FLS", 5},
      {"AUTO_ENA", 6},
      {"AUTO_I1", 7},
      {"AUTO_I2", 8},
      {"AUTO_I3", 9},
      {"AUTO_I4", 10},
      {"AUTO_I5", 11},
      {"AUTO_I6", 12},
      {"AUTO_HM", 13},
      {"AUTO_HY", 14},
      {"AUTO_PERR", 15},
  }};
  if (name.size() < 7 || name.substr(0, 4) != "AUTO") return nullptr;  // most names: at once
  for (const AutoRoutineName& n : kNames)
    if (n.name == name) return &n;
  return nullptr;
}

}  // namespace uprog::gold
