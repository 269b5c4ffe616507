// The ST compiler's driver (compile.h).
#include "dialects/st/compile.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "bytecode/peephole.h"
#include "dialects/st/ascii_table.h"
#include "dialects/st/codegen.h"
#include "dialects/st/lexer.h"
#include "dialects/st/names.h"
#include "dialects/st/parser.h"
#include "preproc/preprocess.h"
#include "support/files.h"

namespace uprog::st {
namespace {

int directive_code(preproc::PreprocError) { return static_cast<int>(Error::BadDirective); }
const char* directive_text(preproc::PreprocError) { return error_text(Error::BadDirective); }

// An #IF condition in the shared preprocessor's C operators: `=` is `==`, `<>` `!=`, AND OR
// NOT MOD `&&` `||` `!` `%`. Only `=` grows the line (by one column).
std::string c_condition(std::string_view line) {
  std::string out;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    const char prev = i > 0 ? line[i - 1] : ' ', next = i + 1 < line.size() ? line[i + 1] : ' ';
    if (c == '<' && next == '>') {
      out += "!=";
      ++i;
    } else if (c == '=' && prev != '<' && prev != '>' && prev != '=' && prev != '!' &&
               next != '=') {
      out += "==";
    } else if (std::isalpha(static_cast<unsigned char>(c)) &&
               !std::isalnum(static_cast<unsigned char>(prev)) && prev != '_') {
      size_t e = i;
      while (e < line.size() &&
             (std::isalnum(static_cast<unsigned char>(line[e])) || line[e] == '_'))
        ++e;
      const std::string w = upper(line.substr(i, e - i));
      out += w == "AND"   ? "&& "
             : w == "OR"  ? "||"
             : w == "NOT" ? "!  "
             : w == "MOD" ? "%  "
                          : std::string(line.substr(i, e - i));
      i = e - 1;
    } else {
      out.push_back(c);
    }
  }
  return out;
}

// The drive writes its directives in capitals (#IF, #DEFINE): the shared preprocessor reads
// them in small letters, at the same columns, and its conditions in C's operators.
std::string lower_directives(const std::string& text) {
  std::string out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    const size_t hash = line.find_first_not_of(" \t");
    if (hash != std::string::npos && line[hash] == '#') {
      size_t k = hash + 1;
      for (; k < line.size() && std::isalpha(static_cast<unsigned char>(line[k])); ++k)
        line[k] = static_cast<char>(std::tolower(static_cast<unsigned char>(line[k])));
      const std::string word = line.substr(hash + 1, k - hash - 1);
      if (word == "if" || word == "elseif")
        line = line.substr(0, k) + c_condition(std::string_view(line).substr(k));
    }
    out += line;
    if (end == text.size()) break;
    out.push_back('\n');
    start = end + 1;
  }
  return out;
}

// The names a source declares, for #IFDEF of a variable, each with the line of its first
// declaration: every word after BYTE, WORD, LONG or DLONG up to the next ';'. A name counts
// only below that line, as a #DEFINE does below its own.
std::map<std::string, int> declared_names(const std::string& text) {
  std::map<std::string, int> out;
  size_t i = 0;
  int line = 1;
  bool in_declaration = false;
  while (i < text.size()) {
    const char c = text[i];
    if (std::isalpha(static_cast<unsigned char>(c))) {
      size_t e = i;
      while (e < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[e])) || text[e] == '_'))
        ++e;
      const std::string w = text.substr(i, e - i);
      const std::string u = upper(w);
      if (u == "BYTE" || u == "WORD" || u == "LONG" || u == "DLONG")
        in_declaration = true;
      else if (in_declaration)
        out.emplace(w, line);
      i = e;
      continue;
    }
    if (c == ';' || c == '\n') in_declaration = false;
    if (c == '\n') ++line;
    ++i;
  }
  return out;
}

void check_limits(const SourceFile& source, Reporter& reporter) {
  const std::string& t = source.text;
  if (t.size() > kMaxSourceBytes)
    reporter.add(Error::SourceTooLong, Location{source.name, 1, 1},
                 std::to_string(t.size()) + " bytes");
  int line = 1;
  for (size_t start = 0; start <= t.size(); ++line) {
    size_t end = t.find('\n', start);
    if (end == std::string::npos) end = t.size();
    size_t length = end - start;
    if (length > 0 && t[end - 1] == '\r') --length;
    if (length > kMaxLineLength)
      reporter.add(Error::LineTooLong,
                   Location{source.name, line, static_cast<int>(kMaxLineLength) + 1});
    start = end + 1;
  }
}

}  // namespace

bool CompileResult::ok() const {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return false;
  return true;
}

CompileResult compile(const SourceFile& source, const CompileOptions& options) {
  CompileResult result;
  const bool preprocess = source.text.find('#') != std::string::npos;
  preproc::Preprocessed pre;
  DiagnosticList pre_diags;
  if (preprocess) {
    preproc::PreprocOptions po;
    po.scheme = kScheme;
    po.code_of = directive_code;
    po.text_of = directive_text;
    po.max_name_length = 10;
    po.star_star_comments = false;
    po.block_comments = false;
    po.string_quote = '\'';
    po.unknown_hash_lines_pass_through = false;
    const std::map<std::string, int> declared = declared_names(source.text);
    po.predefined = [&](std::string_view name, std::optional<int32_t>& value, int line) {
      if (auto d = declared.find(std::string(name)); d != declared.end() && d->second < line)
        return true;
      if (auto d = options.defines.find(name); d != options.defines.end()) {
        value = d->second;
        return true;
      }
      const AsciiEntry* e = find_ascii(name);
      if (e == nullptr || e->kind == AsciiKind::Command || e->kind == AsciiKind::Text) return false;
      value = options.parameter ? options.parameter(name) : std::nullopt;
      if (!value) value = e->default_value;
      return true;
    };
    pre =
        preproc::preprocess(SourceFile{source.name, lower_directives(source.text)}, po, pre_diags);
  }
  const std::string& text = preprocess ? pre.text : source.text;
  preproc::SourceLocator locator(source.name, text, preprocess ? &pre.map : nullptr);
  Reporter reporter(locator);
  check_limits(source, reporter);
  for (Diagnostic& d : pre_diags.items()) reporter.add(std::move(d));

  const std::vector<Token> tokens = lex(text, reporter);
  const Program program = parse(tokens, reporter);
  result.sizes = check(program, reporter);
  if (!reporter.has_errors() && !options.check_only) {
    result.image = generate(program, locator, source.name);
    for (const GlobalVar& g : program.globals)
      result.global_bits.push_back(g.type == VarType::Byte   ? 8
                                   : g.type == VarType::Word ? 16
                                   : g.type == VarType::Long ? 32
                                                             : 64);
    result.image.created_unix_s = options.created_unix_s;
    // The superinstructions on globals (ST has no locals); lines and their ends are kept.
    bytecode::optimize(result.image);
  }
  result.diagnostics = reporter.take();
  // In the order of their places, as the drive lists them; "too many" stays last.
  std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     const bool a_last = a.code == static_cast<int>(Error::TooManyErrors);
                     const bool b_last = b.code == static_cast<int>(Error::TooManyErrors);
                     if (a_last != b_last) return b_last;
                     return std::pair(a.where.line, a.where.column) <
                            std::pair(b.where.line, b.where.column);
                   });
  attach_source_lines(result.diagnostics, source);
  return result;
}

CompileResult compile_file(const std::string& path, const CompileOptions& options) {
  std::string why;
  std::optional<std::string> text = read_text_file(path, &why);
  if (!text) {
    CompileResult r;
    Diagnostic d = make_error(Error::Syntax, Location{path, 0, 0});
    d.message = "cannot read the file: " + why;
    r.diagnostics.push_back(std::move(d));
    return r;
  }
  return compile(SourceFile{path, std::move(*text)}, options);
}

}  // namespace uprog::st
