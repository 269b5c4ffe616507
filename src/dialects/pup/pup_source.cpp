// The PUP compiler's reading side: files and #include, comments, the directives, and #define
// replacing whole names at token level (so a diagnostic points at the name the user wrote).
#include <filesystem>

#include "dialects/pup/builtin_header.h"
#include "dialects/pup/cup_loader.h"
#include "dialects/pup/keywords.h"
#include "dialects/pup/message.h"
#include "dialects/pup/pup_compiler_impl.h"
#include "support/files.h"

namespace uprog::pup {
namespace {

constexpr size_t kMaxIncludeDepth = 16;
constexpr int kMaxDefineDepth = 16;
constexpr size_t kMaxLineTokens = 4096;  // after #define replacement: keeps `#define A B B` finite

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

bool ends_with_ignoring_case(const std::string& s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i])
      return false;
  }
  return true;
}

}  // namespace

bool PupOutput::ok() const {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error) return false;
  }
  return true;
}

void PupCompiler::error(Error e, const Location& at, const std::string& detail) {
  out_.diagnostics.push_back(make_error(e, at, detail));
}

PupOutput PupCompiler::run(const std::string& path, const std::string& text) {
  out_.program.name = std::filesystem::path(path).stem().string();
  include_stack_.push_back(path);
  read_text(path, text, false);
  finish();
  // The flash sector: ADownloadUProg[1] takes at most 262 144 characters of CUP.
  if (const std::string why = out_.ok() ? flash_refusal(write_cup(out_.program).size()) : "";
      !why.empty()) {
    error(Error::ProgramTooLarge, Location{path, 1, 1}, why);
  }
  if (out_.ok()) refuse_what_the_loader_refuses(path);
  out_.vars = vars_;
  return std::move(out_);
}

// Message lines pass into the CUP as written (`AJump[1],301`), so the program the compiler made
// may still be one the controller's loader refuses: its refusal, at the source of the CUP line.
void PupCompiler::refuse_what_the_loader_refuses(const std::string& path) {
  std::string why;
  uint32_t line = 0;
  if (load_cup(out_.program, &why, &line)) return;
  const bool placed = line >= 1 && line <= out_.places.size();
  error(Error::LoaderRefuses, placed ? out_.places[line - 1] : Location{path, 1, 1}, "CUP " + why);
}

// Lines end at CR LF, LF or CR.
void PupCompiler::read_text(const std::string& path, const std::string& text, bool header) {
  int number = 1;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != '\r' && text[i] != '\n') continue;
    line(text.substr(start, i - start), Location{path, number, 1}, header, path);
    if (i + 1 < text.size() && text[i] == '\r' && text[i + 1] == '\n') ++i;
    start = i + 1;
    ++number;
    if (out_.diagnostics.size() > 100) return;  // enough to fix first
  }
}

void PupCompiler::line(const std::string& raw, const Location& at, bool header,
                       const std::string& path) {
  std::string text = raw.substr(0, raw.find("//"));
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return;
  Location where = at;
  where.column = static_cast<int>(first) + 1;
  text = text.substr(first);
  if (text[0] == '#') {
    directive(trim(text), where, path);
    return;
  }
  if (header) {
    error(Error::StatementInHeader, where);
    return;
  }
  auto tokens = tokens_of(text, where);
  if (tokens) statement(*tokens, where);
}

std::optional<std::vector<Token>> PupCompiler::tokens_of(const std::string& text,
                                                         const Location& at) {
  auto tokens = tokenize(text, at, out_.diagnostics);
  if (tokens) expand(*tokens, 0);
  return tokens;
}

// Replaces every name that is a #define by its tokens, placed where the name stood.
void PupCompiler::expand(std::vector<Token>& tokens, int depth) {
  bool changed = false;
  std::vector<Token> out;
  for (const Token& t : tokens) {
    auto d = t.kind == TokenKind::Name ? defines_.find(t.text) : defines_.end();
    if (d == defines_.end()) {
      out.push_back(t);
      continue;
    }
    changed = true;
    if (out.size() + d->second.tokens.size() > kMaxLineTokens || depth >= kMaxDefineDepth) {
      error(Error::DefineTooLong, t.where, "'" + t.text + "'");
      tokens.clear();
      return;
    }
    for (Token r : d->second.tokens) {
      r.where = t.where;
      out.push_back(std::move(r));
    }
  }
  tokens = std::move(out);
  if (changed) expand(tokens, depth + 1);
}

void PupCompiler::directive(const std::string& text, const Location& at, const std::string& path) {
  const size_t space = text.find_first_of(" \t");
  const std::string word = text.substr(0, space);
  const std::string rest = space == std::string::npos ? "" : trim(text.substr(space));
  Location rest_at = at;
  rest_at.column = at.column + static_cast<int>(text.size() - rest.size());
  if (word == "#include")
    include(rest, rest_at, path);
  else if (word == "#define")
    define(rest, rest_at);
  else if (word == "#definevar")
    definevar(rest, rest_at);
  else if (word == "#information")
    out_.program.info.push_back(rest);
  else if (word == "#event")
    event(rest, rest_at);
  else
    error(Error::BadDirective, at, "'" + word + "'");
}

void PupCompiler::include(const std::string& raw, const Location& at, const std::string& path) {
  std::string name = raw;
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
    name = name.substr(1, name.size() - 2);
  if (name.empty()) return error(Error::BadDirective, at, "#include needs a file name");
  if (!ends_with_ignoring_case(name, ".puh"))
    return error(Error::IncludeNotHeader, at, "'" + name + "'");
  if (include_stack_.size() >= kMaxIncludeDepth)
    return error(Error::IncludeLoop, at, "'" + name + "'");
  // Beside the includer, then (a header's #include without a path) beside the .pup.
  std::filesystem::path full = std::filesystem::path(path).parent_path() / name;
  std::string why;
  const auto read_one = [&](const std::filesystem::path& p) {
    return includes_.read(p.string(), &why, [](const std::string& f, std::string* w) {
      return read_text_file(f, w);
    });
  };
  std::optional<std::string> text = read_one(full);
  if (!text && include_stack_.size() > 1 && std::filesystem::path(name).parent_path().empty()) {
    full = std::filesystem::path(include_stack_.front()).parent_path() / name;
    text = read_one(full);
  }
  // Then the folders an editor's workspace gives (`uprog lsp`).
  for (size_t f = 0;
       !text && std::filesystem::path(name).is_relative() && f < includes_.folders.size(); ++f) {
    const std::filesystem::path elsewhere = std::filesystem::path(includes_.folders[f]) / name;
    if ((text = read_one(elsewhere))) full = elsewhere;
  }
  std::string shown = full.string();
  if (!text && name == kBuiltinHeaderName) {
    text = std::string(kBuiltinHeader);
    shown = std::string(kBuiltinHeaderName);
  }
  if (!text) return error(Error::IncludeNotFound, at, "'" + name + "'");
  for (const std::string& open : include_stack_) {
    if (open == shown) return error(Error::IncludeLoop, at, "'" + name + "'");
  }
  include_stack_.push_back(shown);
  read_text(shown, *text, true);
  include_stack_.pop_back();
}

void PupCompiler::define(const std::string& rest, const Location& at) {
  const size_t space = rest.find_first_of(" \t");
  const std::string name = rest.substr(0, space);
  const std::string value = space == std::string::npos ? "" : trim(rest.substr(space));
  bool valid =
      !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
  for (char c : name) valid = valid && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!valid) return error(Error::BadDirective, at, "#define needs a name");
  if (auto old = defines_.find(name); old != defines_.end()) {
    if (old->second.text != value) error(Error::Redefined, at, "'" + name + "'");
    return;
  }
  Location value_at = at;
  value_at.column = at.column + static_cast<int>(rest.size() - value.size());
  auto tokens = tokens_of(value, value_at);  // defines before it are replaced now
  if (tokens) defines_[name] = Define{std::move(*tokens), value, at};
}

// `Name AGenData[N]` or `Name[S] AGenData[N]` (the manual writes GenData[N] too).
void PupCompiler::definevar(const std::string& rest, const Location& at) {
  auto tokens = tokens_of(rest, at);
  if (!tokens) return;
  TokenCursor cur(*tokens, at);
  auto number = [&](int32_t& v) {
    if (cur.at_end() || cur.peek()->kind != TokenKind::Number) return false;
    const auto n = parse_number(cur.take().text, true);
    v = n.value_or(0);
    return n.has_value();
  };
  if (cur.at_end() || cur.peek()->kind != TokenKind::Name)
    return error(Error::BadDirective, at, "#definevar needs a name");
  const Token name = cur.take();
  Var var;
  var.defined_at = name.where;
  if (cur.take_if("[")) {
    var.array = true;
    if (!number(var.size) || !cur.take_if("]") || var.size < 1)
      return error(Error::BadDirective, at, "bad array size");
  }
  const Token* place = cur.peek();
  if (place == nullptr || (place->text != "AGenData" && place->text != "GenData")) {
    return error(Error::BadDirective, at, "the place of a variable is AGenData[N]");
  }
  cur.take();
  if (!cur.take_if("[") || !number(var.base) || !cur.take_if("]") || !cur.at_end()) {
    return error(Error::BadDirective, at, "the place of a variable is AGenData[N]");
  }
  if (var.base < 1 || var.base + var.size - 1 > 1000) {
    return error(Error::OverlappingVariable, name.where, "'" + name.text + "'");
  }
  if (find_keyword(name.text) != nullptr)
    return error(Error::Redefined, name.where, "'" + name.text + "' is a keyword");
  if (vars_.count(name.text) != 0)
    return error(Error::Redefined, name.where, "'" + name.text + "'");
  vars_[name.text] = var;
}

void PupCompiler::event(const std::string& rest, const Location& at) {
  auto tokens = tokens_of(rest, at);
  if (!tokens) return;
  TokenCursor cur(*tokens, at);
  const auto id = constant(cur, "an event ID", false);
  if (!id) return;
  const Location function_at = cur.where();
  const auto function = constant(cur, "a function number", true);
  if (!function) return;
  if (*id < 0 || *id > 23) return error(Error::BadEvent, at, std::to_string(*id));
  for (const CupEvent& e : out_.program.events) {
    if (e.event == *id) return error(Error::DuplicateEvent, at, std::to_string(*id));
  }
  out_.program.events.push_back({*id, *function});
  events_.push_back({*function, function_at});
}

PupOutput compile_pup(const std::string& path, const std::string& text, uint64_t created_unix_s,
                      const IncludeSearch& includes) {
  return PupCompiler(created_unix_s, includes).run(path, text);
}

PupOutput compile_pup_file(const std::string& path, uint64_t created_unix_s) {
  std::string why;
  const auto text = read_text_file(path, &why);
  if (!text) {
    PupOutput out;
    out.diagnostics.push_back(make_error(Error::IncludeNotFound, Location{path, 0, 0}, why));
    return out;
  }
  return compile_pup(path, *text, created_unix_s);
}

}  // namespace uprog::pup
