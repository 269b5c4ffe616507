// Semantic tokens (analysis.h): each word coloured as the dialect knows it — a drive command or
// system variable, a built-in, a keyword, or the user's function, variable, macro or label —
// rather than as a regular expression guesses.
#include <map>

#include "lsp/analysis.h"

namespace uprog::lsp {
namespace {

using json = nlohmann::json;

// The legend's order is the token type's number.
enum TokenType : int {
  kKeyword,
  kFunction,
  kVariable,
  kParameter,
  kMacro,
  kLabel,
  kProperty,
  kNamespace,
};
constexpr int kDeclaration = 1, kDefaultLibrary = 2, kReadonly = 4;

int type_of(dialect::SymbolKind k) {
  switch (k) {
    case dialect::SymbolKind::Function:
      return kFunction;
    case dialect::SymbolKind::Task:
      return kNamespace;
    case dialect::SymbolKind::Label:
      return kLabel;
    case dialect::SymbolKind::Variable:
      return kVariable;
    case dialect::SymbolKind::Parameter:
      return kParameter;
    case dialect::SymbolKind::Macro:
      return kMacro;
  }
  return kVariable;
}

}  // namespace

json semantic_token_legend() {
  return {
      {"tokenTypes",
       {"keyword", "function", "variable", "parameter", "macro", "label", "property", "namespace"}},
      {"tokenModifiers", {"declaration", "defaultLibrary", "readonly"}}};
}

json semantic_tokens(const Analysis& a, const Workspace& ws) {
  // The names the included files declare at their top (a header's procedure, a .puh's #define).
  std::map<std::string, dialect::SymbolKind, std::less<>> included;
  for (const IncludedSymbol& s : included_symbols(a, ws))
    included.emplace(s.symbol.name, s.symbol.kind);
  std::vector<int64_t> data;
  int64_t last_line = 0, last_char = 0;
  for (const dialect::SourceWord& w : a.words()) {
    int type = -1, modifiers = 0;
    const std::string_view name = Analysis::name_of(w);
    if (const dialect::SourceSymbol* s = a.symbol_for(name, w.line)) {
      type = type_of(s->kind);
      if (s->line == w.line) modifiers |= kDeclaration;
    } else if (const auto inc = included.find(name); inc != included.end()) {
      type = type_of(inc->second);
    } else if (a.reference() != nullptr) {
      if (const dialect::ReferenceEntry* e = a.reference()->find(w.text)) {
        switch (e->kind) {
          case dialect::ReferenceKind::Keyword:
          case dialect::ReferenceKind::Directive:
            type = kKeyword;
            break;
          case dialect::ReferenceKind::Function:
            type = kFunction;
            modifiers |= kDefaultLibrary;
            break;
          case dialect::ReferenceKind::Constant:
            type = kMacro;
            modifiers |= kDefaultLibrary | kReadonly;
            break;
          case dialect::ReferenceKind::Command:
          case dialect::ReferenceKind::SystemVariable:
            type = kProperty;
            modifiers |= kDefaultLibrary;
            if (e->access == "read only") modifiers |= kReadonly;
            break;
        }
      }
    }
    if (type < 0) continue;
    const Position p = a.position(w.offset);
    const Position end = a.position(w.offset + w.text.size());
    data.push_back(p.line - last_line);
    data.push_back(p.line == last_line ? p.character - last_char : p.character);
    data.push_back(end.character - p.character);
    data.push_back(type);
    data.push_back(modifiers);
    last_line = p.line;
    last_char = p.character;
  }
  return {{"data", std::move(data)}};
}

}  // namespace uprog::lsp
