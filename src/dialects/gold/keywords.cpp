// Keyword and auto-routine name tables.
#include "dialects/gold/keywords.h"

#include <array>

namespace uprog::gold {

Keyword keyword_of(std::string_view word) {
  struct Entry {
    std::string_view text;
    Keyword kw;
  };
  static constexpr std::array<Entry, 24> kWords = {{
      {"break", Keyword::Break}, {"case", Keyword::Case}, {"catch", Keyword::Catch},
      {"continue", Keyword::Continue}, {"else", Keyword::Else}, {"elseif", Keyword::Elseif},
      {"end", Keyword::End}, {"exit", Keyword::Exit}, {"float", Keyword::Float},
      {"for", Keyword::For}, {"function", Keyword::Function}, {"global", Keyword::Global},
      {"goto", Keyword::Goto}, {"if", Keyword::If}, {"int", Keyword::Int},
      {"otherwise", Keyword::Otherwise}, {"reset", Keyword::Reset}, {"return", Keyword::Return},
      {"switch", Keyword::Switch}, {"try", Keyword::Try}, {"until", Keyword::Until},
      {"wait", Keyword::Wait}, {"while", Keyword::While}, {"nargout", Keyword::Nargout},
  }};
  if (word.size() < 2 || word.size() > 9) return Keyword::None;
  char lower[10];
  for (size_t i = 0; i < word.size(); ++i) {
    const char c = word[i];
    lower[i] = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;  // ASCII only
  }
  const std::string_view w(lower, word.size());
  for (const Entry& e : kWords)  // the first letter first: most names are no keyword
    if (e.text[0] == w[0] && e.text == w) return e.kw;
  return Keyword::None;
}

const AutoRoutineName* find_auto_routine(std::string_view name) {
  static constexpr std::array<AutoRoutineName, 16> kNames = {{
      {"AUTOEXEC", 0}, {"AUTO_ER", 1}, {"AUTO_STOP", 2}, {"AUTO_BG", 3}, {"AUTO_RLS", 4},
      {"AUTO_FLS", 5}, {"AUTO_ENA", 6}, {"AUTO_I1", 7}, {"AUTO_I2", 8}, {"AUTO_I3", 9},
      {"AUTO_I4", 10}, {"AUTO_I5", 11}, {"AUTO_I6", 12}, {"AUTO_HM", 13}, {"AUTO_HY", 14},
      {"AUTO_PERR", 15},
  }};
  for (const AutoRoutineName& n : kNames)
    if (n.name == name) return &n;
  return nullptr;
}

}  // namespace uprog::gold
