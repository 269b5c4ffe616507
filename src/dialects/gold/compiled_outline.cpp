// Gold's declarations as its own front end finds them (outline.h): the preprocessor, lexer and
// parser the compiler runs, their places mapped back onto the source as written. A source they
// refuse gets none, and the editor falls back on the word scanner (outline.cpp).
#include <algorithm>

#include "dialects/gold/lexer.h"
#include "dialects/gold/outline.h"
#include "dialects/gold/parser.h"
#include "preproc/preprocess.h"

namespace uprog::gold {
namespace {

using dialect::SourceSymbol;
using dialect::SymbolKind;

std::string type_name(VarType type, int32_t length) {
  std::string name = type == VarType::Int ? "int" : "float";
  if (length > 0) name += "[" + std::to_string(length) + "]";
  return name;
}

// The declaration's line as written, from its first word to a comment: a function's form.
std::string line_form(std::string_view text, int line) {
  size_t at = 0;
  for (int l = 1; l < line && at != std::string_view::npos; ++l) {
    at = text.find('\n', at);
    if (at != std::string_view::npos) ++at;
  }
  if (at == std::string_view::npos) return "";
  std::string_view form = dialect::rest_of_line(text, at);
  form = form.substr(0, form.find("//"));
  while (!form.empty() && (form.front() == ' ' || form.front() == '\t')) form.remove_prefix(1);
  while (!form.empty() && (form.back() == ' ' || form.back() == '\r' || form.back() == '\t'))
    form.remove_suffix(1);
  return std::string(form);
}

class Collector {
 public:
  Collector(std::string_view source, const Locator& locator) : source_(source), locator_(locator) {}

  void add(std::string name, SymbolKind kind, std::string detail, uint32_t offset, int skip,
           std::string scope, int end_line = 0) {
    const Location at = locator_.locate(offset);
    out_.push_back({std::move(name), kind, std::move(detail), at.line, at.column + skip,
                    std::max(end_line, at.line), std::move(scope)});
  }
  int line_of(uint32_t offset) const { return locator_.locate(offset).line; }
  std::string_view source() const { return source_; }

  // Labels stand only at a block's top (the parser refuses them inside a block, error 83).
  void labels(const Block& block, const std::string& scope) {
    for (const StmtPtr& s : block) {
      if (s == nullptr || s->kind != StmtKind::Label) continue;
      add(std::string(s->name), SymbolKind::Label, s->auto_label ? "local label" : "global label",
          s->offset, 2, scope);
    }
  }

  std::vector<SourceSymbol> take() { return std::move(out_); }

 private:
  std::string_view source_;
  const Locator& locator_;
  std::vector<SourceSymbol> out_;
};

}  // namespace

std::optional<std::vector<dialect::SourceSymbol>> compiled_outline(std::string_view text) {
  const SourceFile source{"", std::string(text)};
  preproc::Preprocessed pre;
  DiagnosticList pre_diags;
  const bool preprocess = text.find('#') != std::string_view::npos;  // as compile() decides
  if (preprocess) {
    preproc::PreprocOptions po;
    po.scheme = "gold";
    pre = preproc::preprocess(source, po, pre_diags);
    if (!pre_diags.items().empty()) return std::nullopt;
  }
  const std::string& t = preprocess ? pre.text : source.text;
  const Locator locator(source.name, t, preprocess ? &pre.map : nullptr);
  Reporter reporter(locator, 1);
  Lexer lexer(t, reporter);
  AstArena arena;
  const Program program = parse_program(lexer, reporter, arena);
  if (reporter.has_errors()) return std::nullopt;

  Collector c(text, locator);
  for (const VarDecl& g : program.globals)
    c.add(std::string(g.name), SymbolKind::Variable, type_name(g.type, g.length) + " (global)",
          g.offset, 0, "");
  c.labels(program.top, "");
  for (const FunctionDef& f : program.functions) {
    const std::string name(f.name);
    const int line = c.line_of(f.offset);
    c.add(name, SymbolKind::Function, line_form(text, line), f.offset, 0, "",
          f.has_body ? c.line_of(f.end_offset) : line);
    for (const Param& p : f.outputs)
      c.add(std::string(p.name), SymbolKind::Parameter, type_name(p.type, 0) + " (output)",
            p.offset, 0, name);
    for (const Param& p : f.inputs)
      c.add(std::string(p.name), SymbolKind::Parameter, type_name(p.type, 0) + " (input)", p.offset,
            0, name);
    for (const VarDecl& v : f.locals) {
      c.add(std::string(v.name), SymbolKind::Variable,
            type_name(v.type, v.length) + (v.is_global_redecl ? " (global)" : ""), v.offset, 0,
            v.is_global_redecl ? "" : name);
    }
    c.labels(f.body, name);
  }
  std::vector<SourceSymbol> out = c.take();
  // #define'd names: the preprocessor consumes them, so they are the scanner's.
  for (SourceSymbol& s : outline(text))
    if (s.kind == SymbolKind::Macro) out.push_back(std::move(s));
  std::stable_sort(out.begin(), out.end(), [](const SourceSymbol& a, const SourceSymbol& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  return out;
}

}  // namespace uprog::gold
