// ST's outline (outline.h). Keywords are case-insensitive; `FUNCTION (NAME);` is a call.
#include "dialects/st/outline.h"

#include <string>

#include "dialects/st/names.h"

namespace uprog::st {
namespace {

using dialect::SourceSymbol;
using dialect::SourceWord;
using dialect::SymbolKind;

bool is_type(const std::string& upper_word) {
  return upper_word == "BYTE" || upper_word == "WORD" || upper_word == "LONG" ||
         upper_word == "DLONG";
}

// `V := e` rather than a label `L:`.
bool assignment_follows(std::string_view text, const SourceWord& w) {
  const std::string_view rest = dialect::rest_of_line(text, w.offset + w.text.size());
  const size_t colon = rest.find(':');
  return colon != std::string_view::npos && rest.substr(colon, 2) == ":=";
}

}  // namespace

dialect::WordSyntax word_syntax() {
  dialect::WordSyntax s;
  s.block_comments = false;
  s.paren_star_comments = true;
  s.string_quote = '\'';
  return s;
}

std::vector<dialect::SourceSymbol> outline(std::string_view text) {
  const std::vector<SourceWord> words = dialect::source_words(text, word_syntax());
  std::vector<SourceSymbol> out;
  std::string unit;  // the program or function the words are in
  size_t unit_index = 0;
  for (size_t i = 0; i < words.size(); ++i) {
    const SourceWord& w = words[i];
    const std::string word = upper(w.text);
    const bool same_line_next = i + 1 < words.size() && words[i + 1].line == w.line;
    if ((word == "PROGRAM" || word == "FUNCTION") && same_line_next && w.next != '(') {
      const SourceWord& name = words[i + 1];
      out.push_back(
          {std::string(name.text), SymbolKind::Function, word, w.line, name.column, w.line, ""});
      unit = std::string(name.text);
      unit_index = out.size() - 1;
    } else if ((word == "END_PROGRAM" || word == "END_FUNCTION") && !unit.empty()) {
      out[unit_index].end_line = w.line;
      unit.clear();
    } else if (word == "#DEFINE" && same_line_next) {
      const std::string_view value =
          dialect::rest_of_line(text, words[i + 1].offset + words[i + 1].text.size());
      out.push_back({std::string(words[i + 1].text), SymbolKind::Macro,
                     std::string(value.substr(0, value.find("//"))), w.line, words[i + 1].column,
                     w.line, ""});
    } else if (unit.empty() && is_type(word) && w.line_start) {
      const std::string_view rest = dialect::rest_of_line(text, w.offset + w.text.size());
      for (const auto& [name, at] : dialect::declared_names(rest)) {
        out.push_back({std::string(name), SymbolKind::Variable, word, w.line,
                       w.column + static_cast<int>(w.text.size() + at), w.line, ""});
      }
    } else if (w.line_start && w.next == ':' && !unit.empty() && !assignment_follows(text, w)) {
      out.push_back(
          {std::string(w.text), SymbolKind::Label, "label", w.line, w.column, w.line, unit});
    }
  }
  return out;
}

}  // namespace uprog::st
