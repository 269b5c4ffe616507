// PDL's outline (outline.h): one pass over the words. A procedure ends where its do block does
// (`else` closes a block and its `do` opens the next, 2.2.8); a task runs to the next #task.
#include "dialects/pdl/outline.h"

#include <string>

namespace uprog::pdl {
namespace {

using dialect::SourceSymbol;
using dialect::SourceWord;
using dialect::SymbolKind;

bool is_type(std::string_view w) {
  return w == "long" || w == "short" || w == "float" || w == "instate";
}

}  // namespace

std::vector<dialect::SourceSymbol> outline(std::string_view text) {
  const std::vector<SourceWord> words = dialect::source_words(text, {});
  std::vector<SourceSymbol> out;
  std::string proc;  // the procedure the words are in
  size_t proc_index = 0;
  int depth = 0;  // do blocks open inside it
  size_t task_index = SIZE_MAX;
  int last_line = 1;
  for (size_t i = 0; i < words.size(); ++i) {
    const SourceWord& w = words[i];
    const bool same_line_next = i + 1 < words.size() && words[i + 1].line == w.line;
    last_line = w.line;
    if (!proc.empty()) {
      if (w.text == "do") ++depth;
      if (w.text == "end" || w.text == "else") --depth;
      if (depth == 0 && w.text == "end") {
        out[proc_index].end_line = w.line;
        proc.clear();
        continue;
      }
    }
    if (w.text == "proc" && w.line_start && same_line_next) {
      const SourceWord& name = words[i + 1];
      const std::string_view form = dialect::rest_of_line(text, w.offset);
      const bool definition = form.find(" do") != std::string_view::npos;
      std::string detail(form.substr(0, form.find(')') + 1));
      out.push_back(
          {std::string(name.text), SymbolKind::Function, detail, w.line, name.column, w.line, ""});
      if (!definition) continue;  // a prototype (1.4)
      proc = std::string(name.text);
      proc_index = out.size() - 1;
      depth = 0;
      for (size_t j = i + 2; j + 1 < words.size() && words[j].line == w.line; ++j) {
        if (!is_type(words[j].text) || words[j + 1].line != w.line) continue;
        // `long * sum` (manual 2.5.1's add3): a pointer's type says so.
        const std::string type = std::string(words[j].text) + (words[j].next == '*' ? "*" : "");
        out.push_back({std::string(words[j + 1].text), SymbolKind::Parameter, type, w.line,
                       words[j + 1].column, w.line, proc});
      }
    } else if (w.line_start && w.text == "#task" && same_line_next) {
      if (task_index != SIZE_MAX) out[task_index].end_line = w.line - 1;
      out.push_back({"task " + std::string(words[i + 1].text), SymbolKind::Task, "#task", w.line,
                     w.column, w.line, ""});
      task_index = out.size() - 1;
    } else if (w.line_start && w.text == "#define" && same_line_next) {
      const std::string_view value =
          dialect::rest_of_line(text, words[i + 1].offset + words[i + 1].text.size());
      out.push_back({std::string(words[i + 1].text), SymbolKind::Macro,
                     std::string(value.substr(0, value.find("//"))), w.line, words[i + 1].column,
                     w.line, ""});
    } else if (w.line_start && (w.text == "#long" || w.text == "#short" || w.text == "#float" ||
                                (!proc.empty() && is_type(w.text)))) {
      // Declared inside a procedure's body, `#long tmp;` is its temporary (manual 2.5.1's add3:
      // "Define temporary user variable"); outside, a global.
      const std::string type(w.text.substr(w.text[0] == '#' ? 1 : 0));
      const std::string_view rest = dialect::rest_of_line(text, w.offset + w.text.size());
      for (const auto& [name, at] : dialect::declared_names(rest)) {
        out.push_back({std::string(name), SymbolKind::Variable,
                       type + (proc.empty() ? " (global)" : " (temporary)"), w.line,
                       w.column + static_cast<int>(w.text.size() + at), w.line, proc});
      }
    } else if (w.line_start && w.next == ':' && !w.text.empty() && w.text[0] != '#' &&
               w.text != "default") {
      out.push_back(
          {std::string(w.text), SymbolKind::Label, "label", w.line, w.column, w.line, proc});
    }
  }
  if (task_index != SIZE_MAX) out[task_index].end_line = last_line;
  return out;
}

}  // namespace uprog::pdl
