// Go to definition, find references, rename, the outline and folding (analysis.h), over the
// dialect's declarations in the document and in the files it includes; references and rename
// reach the open documents that include the file a global name is declared in.
#include <algorithm>
#include <cctype>
#include <deque>

#include "dialect/dialect.h"
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

// What a name under the cursor stands for: a declaration of the document, or of a file it
// includes.
struct Target {
  const TextDocument* file = nullptr;
  SourceSymbol symbol;
};

std::optional<Target> target_at(const Analysis& a, const Workspace& w, Position p) {
  const dialect::SourceWord* word = a.word_at(p);
  if (word == nullptr) return std::nullopt;
  const std::string_view name = Analysis::name_of(*word);
  if (const SourceSymbol* s = a.symbol_for(name, word->line)) return Target{&a.doc(), *s};
  if (std::optional<IncludedSymbol> inc = included_symbol(a, w, name))
    return Target{inc->file, std::move(inc->symbol)};
  return std::nullopt;
}

// The documents a target's name may stand in: its own file, the one asked from, and, for a
// global of a file with a path, every open document that includes that file.
std::vector<const TextDocument*> documents_of(const Target& t, const Analysis& a,
                                              const Workspace& w) {
  std::vector<const TextDocument*> docs = {t.file};
  if (t.file != &a.doc()) docs.push_back(&a.doc());
  if (!t.symbol.scope.empty() || t.file->path.empty()) return docs;
  const std::string file = normal_path(t.file->path);
  for (const TextDocument* d : w.open()) {
    if (std::find(docs.begin(), docs.end(), d) != docs.end() || d->dialect != t.file->dialect)
      continue;
    const std::vector<std::string> includes = w.includes_of(*d, kIncludeDepth);
    if (std::find(includes.begin(), includes.end(), file) != includes.end()) docs.push_back(d);
  }
  return docs;
}

// One word that names the target, in the document `in` (its Analysis).
struct Occurrence {
  const Analysis* in;
  const dialect::SourceWord* word;
  bool declaration;
};

// Every word that names `t`: in its own file those uses_of() finds, elsewhere the words of its
// name the document does not declare itself. `analyses` keeps the documents' analyses.
std::vector<Occurrence> occurrences(const Target& t, const Analysis& a, const Workspace& w,
                                    std::deque<Analysis>& analyses) {
  std::vector<Occurrence> out;
  for (const TextDocument* d : documents_of(t, a, w)) {
    const Analysis& in = d == &a.doc() ? a : analyses.emplace_back(*d, a.reference(), a.encoding());
    if (d == t.file) {
      const auto own = std::find_if(in.symbols().begin(), in.symbols().end(), [&](auto& s) {
        return s.name == t.symbol.name && s.line == t.symbol.line && s.column == t.symbol.column;
      });
      if (own == in.symbols().end()) continue;
      for (const dialect::SourceWord* word : in.uses_of(*own)) {
        const int name_column =
            word->column + static_cast<int>(word->text.size() - Analysis::name_of(*word).size());
        out.push_back({&in, word, word->line == own->line && name_column == own->column});
      }
      continue;
    }
    for (const dialect::SourceWord& word : in.words()) {
      const std::string_view name = Analysis::name_of(word);
      if (name == t.symbol.name && in.symbol_for(name, word.line) == nullptr)
        out.push_back({&in, &word, false});
    }
  }
  return out;
}

// A rename to a name already declared beside the symbol (in its scope, or at the top of its
// file or a file that includes) would make the two one: refused.
void refuse_clash(const Analysis& own, const Workspace& w, const SourceSymbol& symbol,
                  const std::string& new_name) {
  const SourceSymbol* clash = own.symbol_for(new_name, symbol.line);
  if (clash != nullptr && clash->scope == symbol.scope)
    throw FeatureError("'" + new_name + "' is already declared on line " +
                       std::to_string(clash->line) + ": the two names would become one");
  if (!symbol.scope.empty()) return;
  if (const std::optional<IncludedSymbol> inc = included_symbol(own, w, new_name))
    throw FeatureError("'" + new_name + "' is already declared in " + inc->file->uri + " on line " +
                       std::to_string(inc->symbol.line) + ": the two names would become one");
}

}  // namespace

std::optional<IncludedSymbol> included_symbol(const Analysis& a, const Workspace& w,
                                              std::string_view name) {
  if (a.doc().dialect == nullptr) return std::nullopt;
  for (const std::string& file : w.includes_of(a.doc(), kIncludeDepth)) {
    const TextDocument* d = w.load(file, a.doc());
    if (d == nullptr) continue;
    for (SourceSymbol& s : a.doc().dialect->outline(d->text))
      if (s.name == name && s.scope.empty()) return IncludedSymbol{d, std::move(s)};
  }
  return std::nullopt;
}

std::vector<IncludedSymbol> included_symbols(const Analysis& a, const Workspace& w) {
  std::vector<IncludedSymbol> out;
  if (a.doc().dialect == nullptr) return out;
  for (const std::string& file : w.includes_of(a.doc(), kIncludeDepth)) {
    const TextDocument* d = w.load(file, a.doc());
    if (d == nullptr) continue;
    for (SourceSymbol& s : a.doc().dialect->outline(d->text))
      if (s.scope.empty()) out.push_back({d, std::move(s)});
  }
  return out;
}

json definition(const Analysis& a, const Workspace& w, Position p) {
  const std::optional<Target> t = target_at(a, w, p);
  if (!t) return nullptr;
  if (t->file == &a.doc()) return {{"uri", a.doc().uri}, {"range", a.symbol_range(t->symbol)}};
  const Analysis there(*t->file, a.reference(), a.encoding());
  return {{"uri", t->file->uri}, {"range", there.symbol_range(t->symbol)}};
}

json references(const Analysis& a, const Workspace& w, Position p, bool include_declaration) {
  json out = json::array();
  const std::optional<Target> t = target_at(a, w, p);
  if (!t) return out;
  std::deque<Analysis> analyses;
  for (const Occurrence& o : occurrences(*t, a, w, analyses)) {
    if (o.declaration && !include_declaration) continue;
    out.push_back({{"uri", o.in->doc().uri}, {"range", o.in->name_range(*o.word)}});
  }
  return out;
}

// What a rename at `p` renames; FeatureError saying why when there is nothing the program may
// rename there.
Target renamed_at(const Analysis& a, const Workspace& w, Position p) {
  const dialect::SourceWord* word = a.word_at(p);
  if (word == nullptr) throw FeatureError("there is no name here to rename");
  const std::string old_name(Analysis::name_of(*word));
  std::optional<Target> t = target_at(a, w, p);
  if (!t) {
    const dialect::ReferenceEntry* e =
        a.reference() != nullptr ? a.reference()->find(old_name) : nullptr;
    if (e != nullptr)
      throw FeatureError("'" + old_name + "' is a " + kind_name(e->kind) +
                         " of the language or the drive, not a name of the program's: it is "
                         "not renamed");
    throw FeatureError("'" + old_name +
                       "' is declared neither in this document nor in a file it includes");
  }
  if (t->symbol.kind == SymbolKind::Task) throw FeatureError("a task is named by its number");
  return std::move(*t);
}

json prepare_rename(const Analysis& a, const Workspace& w, Position p) {
  const Target t = renamed_at(a, w, p);
  const dialect::SourceWord* word = a.word_at(p);
  return {{"range", a.name_range(*word)}, {"placeholder", t.symbol.name}};
}

json rename(const Analysis& a, const Workspace& w, Position p, const std::string& new_name) {
  const Target t = renamed_at(a, w, p);
  const std::string old_name = t.symbol.name;
  if (!is_name(new_name))
    throw FeatureError("'" + new_name +
                       "' is not a name (a letter or '_', then letters, digits "
                       "and '_')");
  if (const dialect::ReferenceEntry* e =
          a.reference() != nullptr ? a.reference()->find(new_name) : nullptr)
    throw FeatureError("'" + new_name + "' is a " + kind_name(e->kind) +
                       " of the language or the drive: a program's name cannot be it");
  if (new_name != old_name)
    refuse_clash(Analysis(*t.file, a.reference(), a.encoding()), w, t.symbol, new_name);
  std::deque<Analysis> analyses;
  json changes = json::object();
  for (const Occurrence& o : occurrences(t, a, w, analyses)) {
    json& edits = changes[o.in->doc().uri];
    if (edits.is_null()) edits = json::array();
    edits.push_back({{"range", o.in->name_range(*o.word)}, {"newText", new_name}});
  }
  return {{"changes", std::move(changes)}};
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
