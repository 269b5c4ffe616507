// Go to definition, find references, rename, the outline and folding (analysis.h), over the
// dialect's declarations in the document.
#include <cctype>

#include "lsp/analysis.h"

namespace uprog::lsp {
namespace {

using json = nlohmann::json;
using dialect::SourceSymbol;
using dialect::SymbolKind;

// LSP 3.17 SymbolKind.
int lsp_symbol_kind(SymbolKind k) {
  switch (k) {
    case SymbolKind::Function:
      return 12;  // Function
    case SymbolKind::Task:
      return 2;  // Module
    case SymbolKind::Label:
      return 20;  // Key
    case SymbolKind::Variable:
    case SymbolKind::Parameter:
      return 13;  // Variable
    case SymbolKind::Macro:
      return 14;  // Constant
  }
  return 13;
}

const SourceSymbol* symbol_under(const Analysis& a, Position p) {
  const dialect::SourceWord* w = a.word_at(p);
  return w == nullptr ? nullptr : a.symbol_for(Analysis::name_of(*w), w->line);
}

bool is_name(const std::string& s) {
  if (s.empty() || (std::isalpha(static_cast<unsigned char>(s[0])) == 0 && s[0] != '_'))
    return false;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') return false;
  return true;
}

json symbol_json(const Analysis& a, const SourceSymbol& s, bool hierarchical) {
  const json whole = a.lines_range(s.line, std::max(s.end_line, s.line));
  json j = {{"name", s.name}, {"kind", lsp_symbol_kind(s.kind)}};
  if (!s.detail.empty()) j["detail"] = s.detail;
  if (hierarchical) {
    j["range"] = whole;
    j["selectionRange"] = a.symbol_range(s);
  } else {
    j["location"] = {{"uri", a.doc().uri}, {"range", whole}};
    if (!s.scope.empty()) j["containerName"] = s.scope;
  }
  return j;
}

}  // namespace

json definition(const Analysis& a, Position p) {
  const SourceSymbol* s = symbol_under(a, p);
  if (s == nullptr) return nullptr;
  return {{"uri", a.doc().uri}, {"range", a.symbol_range(*s)}};
}

json references(const Analysis& a, Position p, bool include_declaration) {
  const SourceSymbol* s = symbol_under(a, p);
  json out = json::array();
  if (s == nullptr) return out;
  for (const dialect::SourceWord* w : a.uses_of(*s)) {
    const int name_column =
        w->column + static_cast<int>(w->text.size() - Analysis::name_of(*w).size());
    const bool declaration = w->line == s->line && name_column == s->column;
    if (declaration && !include_declaration) continue;
    out.push_back({{"uri", a.doc().uri}, {"range", a.name_range(*w)}});
  }
  return out;
}

json rename(const Analysis& a, Position p, const std::string& new_name) {
  const SourceSymbol* s = symbol_under(a, p);
  if (s == nullptr) throw FeatureError("only a name this document declares can be renamed");
  if (s->kind == SymbolKind::Task) throw FeatureError("a task is named by its number");
  if (!is_name(new_name)) throw FeatureError("'" + new_name + "' is not a name");
  if (a.reference() != nullptr && a.reference()->find(new_name) != nullptr)
    throw FeatureError("'" + new_name + "' is a word of the language or the drive");
  json edits = json::array();
  for (const dialect::SourceWord* w : a.uses_of(*s))
    edits.push_back({{"range", a.name_range(*w)}, {"newText", new_name}});
  return {{"changes", {{a.doc().uri, std::move(edits)}}}};
}

json document_symbols(const Analysis& a, const ClientSupport& client) {
  json out = json::array();
  for (const SourceSymbol& s : a.symbols()) {
    if (!s.scope.empty() && client.hierarchical_symbols) continue;  // a child of its function
    json j = symbol_json(a, s, client.hierarchical_symbols);
    if (client.hierarchical_symbols &&
        (s.kind == SymbolKind::Function || s.kind == SymbolKind::Task)) {
      json children = json::array();
      for (const SourceSymbol& c : a.symbols())
        if (c.scope == s.name && !s.name.empty()) children.push_back(symbol_json(a, c, true));
      if (!children.empty()) j["children"] = std::move(children);
    }
    out.push_back(std::move(j));
  }
  return out;
}

json folding_ranges(const Analysis& a) {
  json out = json::array();
  for (const SourceSymbol& s : a.symbols()) {
    if (s.end_line <= s.line) continue;
    out.push_back({{"startLine", s.line - 1}, {"endLine", s.end_line - 1}, {"kind", "region"}});
  }
  return out;
}

}  // namespace uprog::lsp
