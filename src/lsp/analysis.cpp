// The document the features see (analysis.h).
#include "lsp/analysis.h"

#include <algorithm>

#include "dialect/dialect.h"

namespace uprog::lsp {

namespace {

using json = nlohmann::json;
using dialect::SourceSymbol;
using dialect::SourceWord;

}  // namespace

Analysis::Analysis(const TextDocument& doc, const ReferenceIndex* reference,
                   PositionEncoding encoding, const std::vector<SourceSymbol>* outline)
    : doc_(doc), reference_(reference), encoding_(encoding) {
  line_starts_.push_back(0);
  for (size_t i = 0; i < doc.text.size(); ++i)
    if (doc.text[i] == '\n') line_starts_.push_back(i + 1);
  if (doc.dialect != nullptr) {
    symbols_ = outline != nullptr ? *outline : doc.dialect->outline(doc.text);
    words_ = dialect::source_words(doc.text, doc.dialect->word_syntax());
  }
  for (size_t i = 0; i < symbols_.size(); ++i) {
    const SourceSymbol& s = symbols_[i];
    by_name_[s.name].push_back(i);
    if ((s.kind == dialect::SymbolKind::Function || s.kind == dialect::SymbolKind::Task) &&
        s.end_line > s.line)
      scopes_.push_back(i);
  }
  std::sort(scopes_.begin(), scopes_.end(),
            [&](size_t x, size_t y) { return symbols_[x].line < symbols_[y].line; });
}

Position Analysis::position(size_t offset) const {
  offset = std::min(offset, doc_.text.size());
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const size_t line = static_cast<size_t>(it - line_starts_.begin()) - 1;
  const size_t start = line_starts_[line];
  Position p = position_of(std::string_view(doc_.text).substr(start, offset - start),
                           offset - start, encoding_);
  p.line = static_cast<int64_t>(line);
  return p;
}

Position Analysis::position(int line, int column) const {
  if (line < 1 || static_cast<size_t>(line) > line_starts_.size()) return {};
  return position(line_starts_[static_cast<size_t>(line) - 1] +
                  static_cast<size_t>(std::max(column - 1, 0)));
}

size_t Analysis::offset(Position p) const { return offset_of(doc_.text, p, encoding_); }

json Analysis::range(size_t begin, size_t end) const {
  const Position b = position(begin), e = position(end);
  return {{"start", {{"line", b.line}, {"character", b.character}}},
          {"end", {{"line", e.line}, {"character", e.character}}}};
}

json Analysis::name_range(const SourceWord& w) const {
  const size_t skip = w.text.size() - name_of(w).size();
  return range(w.offset + skip, w.offset + w.text.size());
}

json Analysis::symbol_range(const SourceSymbol& s) const {
  if (s.line < 1 || static_cast<size_t>(s.line) > line_starts_.size()) return range(0, 0);
  const size_t begin =
      line_starts_[static_cast<size_t>(s.line) - 1] + static_cast<size_t>(s.column - 1);
  // A task's name ("task 1") is not its text: the range is its marker's word.
  size_t end = begin;
  while (end < doc_.text.size() && doc_.text[end] != '\n' &&
         (std::isalnum(static_cast<unsigned char>(doc_.text[end])) != 0 || doc_.text[end] == '_' ||
          (end == begin && doc_.text[end] == '#')))
    ++end;
  return range(begin, end);
}

json Analysis::lines_range(int first_line, int last_line) const {
  const auto line_end = [&](int line) {
    const size_t l =
        static_cast<size_t>(std::clamp<int>(line, 1, static_cast<int>(line_starts_.size())));
    size_t end = l < line_starts_.size() ? line_starts_[l] - 1 : doc_.text.size();
    if (end > line_starts_[l - 1] && doc_.text[end - 1] == '\r') --end;
    return end;
  };
  const size_t first = line_starts_[static_cast<size_t>(std::clamp<int>(
                                        first_line, 1, static_cast<int>(line_starts_.size()))) -
                                    1];
  return range(first, std::max(first, line_end(last_line)));
}

const SourceWord* Analysis::word_at(Position p) const {
  const size_t at = offset(p);
  const auto it = std::upper_bound(words_.begin(), words_.end(), at,
                                   [](size_t o, const SourceWord& w) { return o < w.offset; });
  if (it == words_.begin()) return nullptr;
  const SourceWord& w = *(it - 1);
  return at <= w.offset + w.text.size() ? &w : nullptr;
}

std::string_view Analysis::name_of(const SourceWord& w) {
  if (w.text.size() > 2 && (w.text.starts_with("##") || w.text.starts_with("#@")))
    return w.text.substr(2);
  return w.text;
}

const SourceSymbol* Analysis::scope_at(int line) const {
  // The last body that starts on or before the line, if the line is inside it.
  const auto it = std::upper_bound(scopes_.begin(), scopes_.end(), line,
                                   [&](int l, size_t i) { return l < symbols_[i].line; });
  if (it == scopes_.begin()) return nullptr;
  const SourceSymbol& s = symbols_[*(it - 1)];
  return line <= s.end_line ? &s : nullptr;
}

const SourceSymbol* Analysis::symbol_for(std::string_view name, int line) const {
  const auto found = by_name_.find(name);
  if (found == by_name_.end()) return nullptr;
  const SourceSymbol* scope = scope_at(line);
  const SourceSymbol* global = nullptr;
  const SourceSymbol* label = nullptr;
  for (size_t i : found->second) {
    const SourceSymbol& s = symbols_[i];
    if (scope != nullptr && s.scope == scope->name) return &s;  // a local of the function here
    if (!s.scope.empty()) {
      // A label of another function (goto from elsewhere): the first of that name.
      if (label == nullptr && s.kind == dialect::SymbolKind::Label) label = &s;
      continue;
    }
    if (global == nullptr ||
        ((s.kind == dialect::SymbolKind::Function || s.kind == dialect::SymbolKind::Task) &&
         global->kind != dialect::SymbolKind::Function))
      global = &s;
  }
  return global != nullptr ? global : label;
}

std::vector<const SourceWord*> Analysis::uses_of(const SourceSymbol& symbol) const {
  std::vector<const SourceWord*> out;
  const SourceSymbol* scope = nullptr;
  if (!symbol.scope.empty()) {
    for (const SourceSymbol& s : symbols_)
      if (s.name == symbol.scope && s.scope.empty() && s.end_line > s.line) scope = &s;
  }
  for (const SourceWord& w : words_) {
    if (name_of(w) != symbol.name) continue;
    if (scope != nullptr && (w.line < scope->line || w.line > scope->end_line)) continue;
    // A global's name inside a function that declares a local of that name is the local's.
    if (scope == nullptr && symbol_for(name_of(w), w.line) != &symbol) continue;
    out.push_back(&w);
  }
  return out;
}

}  // namespace uprog::lsp
