// Hover, completion and signature help (analysis.h): the reference's entries for the drive's
// names and the language's words, the document's declarations for the user's.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "lsp/analysis.h"

namespace uprog::lsp {
namespace {

using json = nlohmann::json;
using dialect::ReferenceKind;
using dialect::SourceSymbol;
using dialect::SymbolKind;

std::string symbol_kind_name(SymbolKind k) {
  switch (k) {
    case SymbolKind::Function:
      return "function";
    case SymbolKind::Task:
      return "task";
    case SymbolKind::Label:
      return "label";
    case SymbolKind::Variable:
      return "variable";
    case SymbolKind::Parameter:
      return "parameter";
    case SymbolKind::Macro:
      return "macro";
  }
  return "";
}

std::string symbol_markdown(const SourceSymbol& s) {
  std::string md = "```\n" + (s.detail.empty() ? s.name : s.detail) + "\n```\n**" + s.name +
                   "**: " + symbol_kind_name(s.kind);
  if (s.kind == SymbolKind::Macro)
    md = "```\n#define " + s.name + s.detail + "\n```\n**" + s.name + "**: macro";
  if (!s.scope.empty()) md += " of " + s.scope;
  md += ", declared on line " + std::to_string(s.line);
  return md;
}

// LSP 3.17 CompletionItemKind.
int completion_kind(ReferenceKind k) {
  switch (k) {
    case ReferenceKind::Command:
      return 10;  // Property
    case ReferenceKind::SystemVariable:
      return 6;  // Variable
    case ReferenceKind::Function:
      return 3;  // Function
    case ReferenceKind::Constant:
      return 21;  // Constant
    case ReferenceKind::Keyword:
    case ReferenceKind::Directive:
      return 14;  // Keyword
  }
  return 1;
}

int completion_kind(SymbolKind k) {
  switch (k) {
    case SymbolKind::Function:
      return 3;  // Function
    case SymbolKind::Task:
      return 9;  // Module
    case SymbolKind::Label:
      return 20;  // EnumMember
    case SymbolKind::Variable:
    case SymbolKind::Parameter:
      return 6;  // Variable
    case SymbolKind::Macro:
      return 21;  // Constant
  }
  return 1;
}

// "sin(x)" → "sin(${1:x})"; "XREAD('NAME', V)" → "XREAD(${1:'NAME'}, ${2:V})".
std::string snippet_of(const std::string& signature) {
  const size_t open = signature.find('('), close = signature.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return signature;
  std::string out = signature.substr(0, open + 1);
  std::string args = signature.substr(open + 1, close - open - 1);
  int n = 1;
  size_t at = 0;
  while (at <= args.size()) {
    size_t comma = args.find(',', at);
    if (comma == std::string::npos) comma = args.size();
    std::string arg = args.substr(at, comma - at);
    while (!arg.empty() && arg.front() == ' ') arg.erase(0, 1);
    if (!arg.empty()) {
      for (char c : std::string("$}\\"))
        for (size_t p = arg.find(c); p != std::string::npos; p = arg.find(c, p + 2))
          arg.insert(p, "\\");
      if (n > 1) out += ", ";
      out += "${" + std::to_string(n++) + ":" + arg + "}";
    }
    at = comma + 1;
  }
  return out + ")";
}

bool starts_with_folded(std::string_view text, std::string_view prefix) {
  if (prefix.size() > text.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(prefix[i])))
      return false;
  return true;
}

// The parameters of "name(a, b)" as the label's character ranges.
json parameter_ranges(const std::string& label) {
  json out = json::array();
  const size_t open = label.find('('), close = label.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close <= open + 1) return out;
  size_t at = open + 1;
  while (at < close) {
    size_t comma = label.find(',', at);
    if (comma == std::string::npos || comma > close) comma = close;
    size_t b = at;
    while (b < comma && label[b] == ' ') ++b;
    if (b < comma) out.push_back({{"label", json::array({b, comma})}});
    at = comma + 1;
  }
  return out;
}

// The name at `p` inside a string or comment: ST's drive commands stand in strings
// (XREAD('VLIM', V), COMMAND('EN')).
json hover_in_text(const Analysis& a, Position p) {
  if (a.reference() == nullptr) return nullptr;
  const std::string& text = a.doc().text;
  const auto name_char = [&](size_t i) {
    return std::isalnum(static_cast<unsigned char>(text[i])) != 0 || text[i] == '_';
  };
  const size_t at = a.offset(p);
  size_t begin = at, end = at;
  while (begin > 0 && name_char(begin - 1)) --begin;
  while (end < text.size() && name_char(end)) ++end;
  if (begin == end) return nullptr;
  const dialect::ReferenceEntry* e =
      a.reference()->find(std::string_view(text).substr(begin, end - begin));
  if (e == nullptr) return nullptr;
  return {{"contents", {{"kind", "markdown"}, {"value", hover_markdown(*e)}}},
          {"range", a.range(begin, end)}};
}

}  // namespace

json hover(const Analysis& a, const Workspace& ws, Position p) {
  const dialect::SourceWord* w = a.word_at(p);
  if (w == nullptr) return hover_in_text(a, p);
  std::string markdown;
  if (const SourceSymbol* s = a.symbol_for(Analysis::name_of(*w), w->line)) {
    markdown = symbol_markdown(*s);
  } else if (std::optional<IncludedSymbol> inc = included_symbol(a, ws, Analysis::name_of(*w))) {
    markdown = symbol_markdown(inc->symbol) + " of " +
               std::filesystem::path(inc->file->path).filename().string();
  } else if (a.reference() != nullptr) {
    const dialect::ReferenceEntry* e = a.reference()->find(w->text);
    if (e == nullptr) return nullptr;
    markdown = hover_markdown(*e);
  } else {
    return nullptr;
  }
  return {{"contents", {{"kind", "markdown"}, {"value", markdown}}}, {"range", a.name_range(*w)}};
}

json completion(const Analysis& a, const Workspace& ws, Position p, const ClientSupport& client) {
  // The prefix typed so far: the word the cursor ends.
  std::string_view prefix;
  if (const dialect::SourceWord* w = a.word_at(p)) {
    const size_t cursor = a.offset(p);
    if (cursor >= w->offset) prefix = w->text.substr(0, cursor - w->offset);
  }
  const int line = static_cast<int>(p.line) + 1;
  json items = json::array();
  std::vector<std::string> seen;
  const auto add = [&](const std::string& label, json item) {
    if (!starts_with_folded(label, prefix)) return;
    if (std::find(seen.begin(), seen.end(), label) != seen.end()) return;
    seen.push_back(label);
    item["label"] = label;
    items.push_back(std::move(item));
  };
  // The user's names first: locals of the function here, then the globals.
  const SourceSymbol* scope = a.scope_at(line);
  for (const SourceSymbol& s : a.symbols()) {
    if (!s.scope.empty() && (scope == nullptr || s.scope != scope->name)) continue;
    if (s.kind == SymbolKind::Task) continue;  // a task is not named in code
    json item = {{"kind", completion_kind(s.kind)},
                 {"detail", s.detail.empty() ? symbol_kind_name(s.kind) : s.detail},
                 {"sortText", "0" + s.name}};
    add(s.name, std::move(item));
  }
  // Then those the included files declare at their top.
  for (const IncludedSymbol& inc : included_symbols(a, ws)) {
    if (inc.symbol.kind == SymbolKind::Task || inc.symbol.kind == SymbolKind::Label) continue;
    const std::string file = std::filesystem::path(inc.file->path).filename().string();
    json item = {{"kind", completion_kind(inc.symbol.kind)},
                 {"detail", (inc.symbol.detail.empty() ? symbol_kind_name(inc.symbol.kind)
                                                       : inc.symbol.detail) +
                                " (" + file + ")"},
                 {"sortText", "0" + inc.symbol.name}};
    add(inc.symbol.name, std::move(item));
  }
  if (a.reference() != nullptr) {
    for (const dialect::ReferenceEntry& e : a.reference()->entries()) {
      json item = {{"kind", completion_kind(e.kind)},
                   {"detail", kind_name(e.kind) + (e.unit.empty() ? "" : ", " + e.unit)},
                   {"documentation", {{"kind", "markdown"}, {"value", hover_markdown(e)}}},
                   {"sortText", "1" + e.name}};
      if (!e.signature.empty() && client.snippets) {
        item["insertText"] = snippet_of(e.signature);
        item["insertTextFormat"] = 2;  // Snippet
      }
      add(e.name, std::move(item));
    }
  }
  return {{"isIncomplete", false}, {"items", std::move(items)}};
}

json signature_help(const Analysis& a, const Workspace& ws, Position p) {
  const std::string& text = a.doc().text;
  const size_t cursor = std::min(a.offset(p), text.size());
  // Back to the '(' of the call whose arguments the cursor is in, counting the commas before the
  // cursor; a '(' with no name before it groups an expression and is passed over.
  int depth = 0;
  size_t commas = 0;
  std::string name;
  for (size_t i = cursor; i > 0 && cursor - i < 2000 && name.empty(); --i) {
    const char c = text[i - 1];
    if (c == '\n' || c == ';') break;
    if (c == ')') ++depth;
    if (c == ',' && depth == 0) ++commas;
    if (c != '(') continue;
    if (depth > 0) {
      --depth;
      continue;
    }
    size_t end = i - 1;
    while (end > 0 && text[end - 1] == ' ') --end;
    size_t begin = end;
    while (begin > 0 && (std::isalnum(static_cast<unsigned char>(text[begin - 1])) != 0 ||
                         text[begin - 1] == '_'))
      --begin;
    name = text.substr(begin, end - begin);
    if (name.empty()) commas = 0;  // a group's commas are not the call's
  }
  if (name.empty()) return nullptr;
  std::string label, documentation;
  std::optional<IncludedSymbol> inc;
  const SourceSymbol* s = a.symbol_for(name, static_cast<int>(p.line) + 1);
  if (s == nullptr && (inc = included_symbol(a, ws, name))) s = &inc->symbol;
  if (s != nullptr && s->kind == SymbolKind::Function) {
    label = s->detail.empty() ? s->name + "()" : s->detail;
    // A Gold function's label is its whole form: the parameters are after the name.
    const size_t at = label.find(s->name + "(");
    const size_t at_spaced = label.find(s->name + " (");
    if (at != std::string::npos)
      label = label.substr(at);
    else if (at_spaced != std::string::npos)
      label = label.substr(at_spaced);
  } else if (a.reference() != nullptr) {
    const dialect::ReferenceEntry* e = a.reference()->find(name);
    if (e == nullptr || e->signature.empty()) return nullptr;
    label = e->signature;
    documentation = e->summary;
  } else {
    return nullptr;
  }
  json signature = {{"label", label}, {"parameters", parameter_ranges(label)}};
  if (!documentation.empty()) signature["documentation"] = documentation;
  return {{"signatures", json::array({signature})},
          {"activeSignature", 0},
          {"activeParameter", commas}};
}

}  // namespace uprog::lsp
