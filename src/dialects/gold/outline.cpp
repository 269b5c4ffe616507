// Gold's outline (outline.h): one pass over the words. A function runs from its `function` line
// to its first `return` outside a block (manual 2.5: "return //end the definition of the
// function"), or to the line before the next function when it has none.
#include "dialects/gold/outline.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace uprog::gold {
namespace {

using dialect::SourceSymbol;
using dialect::SourceWord;
using dialect::SymbolKind;

bool is_type(std::string_view w) { return w == "int" || w == "float"; }

// `function [int x, int y] = name(int a, float b)`: the name, then each typed input and output.
void add_function(std::string_view text, const std::vector<SourceWord>& words, size_t at,
                  std::vector<SourceSymbol>& out) {
  const int line = words[at].line;
  const std::string_view form = dialect::rest_of_line(text, words[at].offset);
  const size_t eq = form.find('=');
  const size_t paren = form.find('(');
  // The name: the first word after `=`, else after `function`.
  size_t k = at + 1;
  if (eq != std::string_view::npos && (paren == std::string_view::npos || eq < paren)) {
    while (k < words.size() && words[k].line == line && words[k].offset < words[at].offset + eq)
      ++k;
  }
  if (k >= words.size() || words[k].line != line) return;
  SourceSymbol f;
  f.name = std::string(words[k].text);
  f.kind = SymbolKind::Function;
  std::string detail(form.substr(0, form.find("//")));
  while (!detail.empty() && (detail.back() == ' ' || detail.back() == '\r')) detail.pop_back();
  f.detail = detail;
  f.line = line;
  f.column = words[k].column;
  f.end_line = line;
  out.push_back(f);
  // Typed names on the line: outputs before the name, inputs after it.
  for (size_t j = at + 1; j + 1 < words.size() && words[j].line == line; ++j) {
    if (!is_type(words[j].text) || words[j + 1].line != line) continue;
    SourceSymbol p;
    p.name = std::string(words[j + 1].text);
    p.kind = SymbolKind::Parameter;
    p.detail = std::string(words[j].text) + (j < k ? " (output)" : " (input)");
    p.line = line;
    p.column = words[j + 1].column;
    p.end_line = line;
    p.scope = f.name;
    out.push_back(p);
  }
}

bool same_folded(std::string_view word, std::string_view keyword) {
  if (word.size() != keyword.size()) return false;
  for (size_t i = 0; i < word.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(word[i])) != keyword[i]) return false;
  return true;
}

// A word that starts a statement: first on its line or after ';' (keywords compare ignoring
// case, gold.md decision 1).
bool starts_statement(std::string_view text, const SourceWord& w) {
  if (w.line_start) return true;
  size_t at = w.offset;
  while (at > 0 && (text[at - 1] == ' ' || text[at - 1] == '\t')) --at;
  return at > 0 && text[at - 1] == ';';
}

// How a statement's first word changes the block depth inside a function: the parser's blocks
// (parser.cpp: if, while, for, switch, try ... end).
int depth_change(std::string_view word) {
  for (std::string_view opener : {"if", "while", "for", "switch", "try"})
    if (same_folded(word, opener)) return 1;
  return same_folded(word, "end") ? -1 : 0;
}

}  // namespace

dialect::WordSyntax word_syntax() {
  dialect::WordSyntax s;
  s.star_star_comments = true;
  return s;
}

std::vector<dialect::SourceSymbol> outline(std::string_view text) {
  const std::vector<SourceWord> words = dialect::source_words(text, word_syntax());
  std::vector<SourceSymbol> out;
  std::string function;  // the function the words are in; "" outside them
  size_t function_index = 0;
  int depth = 0;  // the blocks open in the function
  int last_line = 1;
  for (size_t i = 0; i < words.size(); ++i) {
    const SourceWord& w = words[i];
    last_line = w.line;
    if (!function.empty() && starts_statement(text, w)) {
      // The body ends at its first `return` outside a block, as the parser ends it
      // (parser.cpp, kStopReturn): what follows is the top level's again.
      if (depth == 0 && same_folded(w.text, "return")) {
        out[function_index].end_line = w.line;
        function.clear();
        continue;
      }
      depth = std::max(depth + depth_change(w.text), 0);
    }
    if (w.line_start && w.text == "function") {
      if (!function.empty()) out[function_index].end_line = w.line - 1;
      const size_t before = out.size();
      add_function(text, words, i, out);
      function.clear();
      depth = 0;
      if (out.size() > before) {
        function = out[before].name;
        function_index = before;
      }
    } else if (w.line_start && (w.text == "#define") && i + 1 < words.size() &&
               words[i + 1].line == w.line) {
      const std::string_view value =
          dialect::rest_of_line(text, words[i + 1].offset + words[i + 1].text.size());
      out.push_back({std::string(words[i + 1].text), SymbolKind::Macro,
                     std::string(value.substr(0, value.find("//"))), w.line, words[i + 1].column,
                     w.line, ""});
    } else if (w.line_start && (w.text.starts_with("##") || w.text.starts_with("#@")) &&
               w.text.size() > 2) {
      out.push_back({std::string(w.text.substr(2)), SymbolKind::Label,
                     w.text.starts_with("##") ? "global label" : "local label", w.line,
                     w.column + 2, w.line, function});
    } else if (is_type(w.text) && (w.line_start || (i > 0 && words[i - 1].text == "global" &&
                                                    words[i - 1].line == w.line))) {
      const bool global = function.empty() || (i > 0 && words[i - 1].text == "global");
      const std::string_view rest = dialect::rest_of_line(text, w.offset + w.text.size());
      const int line_column = w.column + static_cast<int>(w.text.size());
      for (const auto& [name, at] : dialect::declared_names(rest)) {
        out.push_back({std::string(name), SymbolKind::Variable,
                       std::string(w.text) + (global ? " (global)" : ""), w.line,
                       line_column + static_cast<int>(at), w.line, global ? "" : function});
      }
    }
  }
  if (!function.empty()) out[function_index].end_line = last_line;
  return out;
}

}  // namespace uprog::gold
