// Go to definition, find references, rename, the outline and folding (analysis.h), over the
// dialect's declarations in the document.
#include <cctype>
#include <filesystem>

#include "dialect/dialect.h"
#include "lsp/analysis.h"
#include "lsp/uri.h"
#include "support/files.h"

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

// The files the document's `#include` lines name (PDL's "scale.h", PUP's lib.puh), beside the
// document, as the compilers find them first; at most 1 MiB each.
std::vector<std::string> included_files(const Analysis& a) {
  std::vector<std::string> files;
  if (a.doc().path.empty()) return files;
  const std::filesystem::path dir = std::filesystem::path(a.doc().path).parent_path();
  const std::vector<dialect::SourceWord>& words = a.words();
  for (size_t i = 0; i < words.size(); ++i) {
    if (!words[i].line_start || words[i].text != "#include") continue;
    std::string_view rest = dialect::rest_of_line(a.doc().text, words[i].offset + 8);
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
    const bool quoted = !rest.empty() && (rest.front() == '"' || rest.front() == '<');
    if (quoted) rest.remove_prefix(1);
    const size_t end = rest.find_first_of(quoted ? "\">" : " \t\r");
    std::string name(rest.substr(0, end));
    for (char& c : name)
      if (c == '\\') c = '/';
    if (name.empty()) continue;
    std::error_code ec;
    const std::filesystem::path file = dir / name;
    if (std::filesystem::is_regular_file(file, ec) &&
        std::filesystem::file_size(file, ec) <= (1u << 20) && !ec)
      files.push_back(file.lexically_normal().string());
  }
  return files;
}

// `name` declared at the top level of an included file: its location, or null.
json included_definition(const Analysis& a, std::string_view name) {
  if (a.doc().dialect == nullptr) return nullptr;
  for (const std::string& file : included_files(a)) {
    const std::optional<std::string> text = read_text_file(file);
    if (!text) continue;
    for (const SourceSymbol& s : a.doc().dialect->outline(*text)) {
      if (s.name != name || !s.scope.empty()) continue;
      const int64_t line = s.line - 1, character = s.column - 1;
      return {
          {"uri", uri_from_path(std::filesystem::absolute(file).string())},
          {"range",
           {{"start", {{"line", line}, {"character", character}}},
            {"end",
             {{"line", line}, {"character", character + static_cast<int64_t>(s.name.size())}}}}}};
    }
  }
  return nullptr;
}

}  // namespace

json definition(const Analysis& a, Position p) {
  if (const SourceSymbol* s = symbol_under(a, p))
    return {{"uri", a.doc().uri}, {"range", a.symbol_range(*s)}};
  // Not declared here: a procedure, function or macro of an included file.
  const dialect::SourceWord* w = a.word_at(p);
  return w == nullptr ? json(nullptr) : included_definition(a, Analysis::name_of(*w));
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
