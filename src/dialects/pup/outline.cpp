// PUP's outline (outline.h): a task or function runs from its marker to the line before the
// next marker; a function is named by its marker's index, a number or a #define'd name.
#include "dialects/pup/outline.h"

#include <string>

namespace uprog::pup {
namespace {

using dialect::SourceSymbol;
using dialect::SourceWord;
using dialect::SymbolKind;

}  // namespace

std::vector<dialect::SourceSymbol> outline(std::string_view text) {
  const std::vector<SourceWord> words = dialect::source_words(text, {});
  std::vector<SourceSymbol> out;
  size_t open = SIZE_MAX;  // the task or function the lines are in
  int last_line = 1;
  for (size_t i = 0; i < words.size(); ++i) {
    const SourceWord& w = words[i];
    const bool same_line_next = i + 1 < words.size() && words[i + 1].line == w.line;
    last_line = w.line;
    if (!w.line_start || !same_line_next) continue;
    const SourceWord& next = words[i + 1];
    if (w.text == "AProgTask" || w.text == "AProgFunc") {
      if (open != SIZE_MAX) out[open].end_line = w.line - 1;
      const bool task = w.text == "AProgTask";
      out.push_back({std::string(task ? "task " : "") + std::string(next.text),
                     task ? SymbolKind::Task : SymbolKind::Function,
                     std::string(w.text) + "[" + std::string(next.text) + "]", w.line,
                     task ? w.column : next.column, w.line, ""});
      open = out.size() - 1;
    } else if (w.text == "#definevar") {
      const std::string_view value = dialect::rest_of_line(text, next.offset + next.text.size());
      std::string detail(value.substr(0, value.find("//")));
      while (!detail.empty() && detail.front() == ' ') detail.erase(0, 1);
      out.push_back(
          {std::string(next.text), SymbolKind::Variable, detail, w.line, next.column, w.line, ""});
    } else if (w.text == "#define") {
      const std::string_view value = dialect::rest_of_line(text, next.offset + next.text.size());
      out.push_back({std::string(next.text), SymbolKind::Macro,
                     std::string(value.substr(0, value.find("//"))), w.line, next.column, w.line,
                     ""});
    }
  }
  if (open != SIZE_MAX) out[open].end_line = last_line;
  return out;
}

}  // namespace uprog::pup
