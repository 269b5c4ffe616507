// The preprocessor's driver: runs directives line by line, keeps the stack of open #if blocks and
// puts the Expander's replacements into the lines that stay. One output line per input line, so
// line numbers survive; the OutputBuilder records where columns moved.
#include "preproc/preprocess.h"

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <vector>

#include "preproc/const_expr.h"
#include "preproc/expander.h"
#include "preproc/line_scanner.h"
#include "preproc/macro_table.h"
#include "preproc/output_builder.h"
#include "support/files.h"

namespace uprog::preproc {
namespace {

enum class Directive {
  Define,
  Undef,
  If,
  Ifdef,
  Ifndef,
  Elseif,
  Else,
  Endif,
  // Extension points: recognised so they can be rejected (or, later, handled) by name.
  Include,
  Elifdef,
  Elifndef,
  Definevar,
  Information,
};

struct DirectiveName {
  std::string_view name;
  Directive directive;
};

constexpr DirectiveName kDirectives[] = {
    {"define", Directive::Define},
    {"undef", Directive::Undef},
    {"if", Directive::If},
    {"ifdef", Directive::Ifdef},
    {"ifndef", Directive::Ifndef},
    {"elseif", Directive::Elseif},
    {"else", Directive::Else},
    {"endif", Directive::Endif},
    {"include", Directive::Include},
    {"elifdef", Directive::Elifdef},
    {"elifndef", Directive::Elifndef},
    {"definevar", Directive::Definevar},
    {"information", Directive::Information},
};

// One open #if/#ifdef/#ifndef block.
struct Conditional {
  Location at;         // the directive that opened it
  bool parent_active;  // the lines around the block are kept
  bool active;         // the lines of the current branch are kept
  bool taken;          // some branch was already kept (or the parent is skipped)
  bool seen_else;
  int elseifs;
};

size_t skip_blanks(std::string_view s, size_t i) {
  while (i < s.size() && is_blank(s[i])) ++i;
  return i;
}
std::string_view trim(std::string_view s) {
  size_t b = skip_blanks(s, 0), e = s.size();
  while (e > b && is_blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}
// Two macro bodies alike but for the amount of whitespace between their tokens (C17 6.10.3 p1).
bool same_but_whitespace(std::string_view a, std::string_view b) {
  auto space = [](char c) { return is_blank(c) || c == '\n' || c == '\r'; };
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (space(a[i]) && space(b[j])) {
      while (i < a.size() && space(a[i])) ++i;
      while (j < b.size() && space(b[j])) ++j;
    } else if (a[i++] != b[j++]) {
      return false;
    }
  }
  return i == a.size() && j == b.size();
}

class Preprocessor {
 public:
  Preprocessor(const SourceFile& source, const PreprocOptions& options, DiagnosticList& diagnostics)
      : source_(&source),
        options_(options),
        diagnostics_(diagnostics),
        out_(source.name, source.text.size()) {}

  Preprocessed run() {
    run_text();
    for (const Conditional& c : stack_)
      report(PreprocError::UnterminatedIf, c.at,
             {{c.at, "this #if has no #endif before the end of the file"}});
    return out_.take();
  }

 private:
  // The lines of the current file (source_), each followed by a newline but the last.
  void run_text() {
    const std::string_view text = source_->text;
    size_t pos = 0;
    std::string continued;  // a #define's lines ending in '\\', joined (function-like macros)
    int continued_from = 0;
    for (line_ = 1;; ++line_) {
      const size_t newline = text.find('\n', pos);
      const size_t end = newline == std::string_view::npos ? text.size() : newline;
      std::string_view line = text.substr(pos, end - pos);
      if (options_.allow_function_macros) {
        std::string_view body = line;
        while (!body.empty() && is_blank(body.back())) body.remove_suffix(1);
        const bool more = !body.empty() && body.back() == '\\' &&
                          newline != std::string_view::npos &&
                          (!continued.empty() || trim(line).starts_with("#define"));
        if (more) {
          if (continued.empty()) continued_from = line_;
          continued.append(body.substr(0, body.size() - 1)).push_back(' ');
          out_.mark(line_, 1);
          out_.append('\n');
          pos = newline + 1;
          continue;
        }
      }
      if (!continued.empty()) {
        // The joined directive is reported at its first line; it writes no text of its own.
        continued.append(line);
        const int last = line_;
        line_ = continued_from;
        process_line(continued);
        line_ = last;
        continued.clear();
      } else {
        process_line(line);
      }
      if (newline == std::string_view::npos) break;
      out_.append('\n');
      pos = newline + 1;
    }
  }

  bool active() const { return stack_.empty() || stack_.back().active; }
  Location here(size_t offset) const {
    return Location{source_->name, line_, static_cast<int>(std::min<size_t>(offset, 1u << 30)) + 1};
  }

  void report(PreprocError e, Location where, std::vector<DiagnosticNote> notes = {}) {
    Diagnostic d;
    d.severity = Severity::Error;
    d.scheme = options_.scheme;
    d.code = (options_.code_of ? options_.code_of : gold_code_of)(e);
    d.message = (options_.text_of ? options_.text_of : gold_text_of)(e);
    d.where = std::move(where);
    d.notes = std::move(notes);
    diagnostics_.add(std::move(d));
  }

  void process_line(std::string_view line) {
    out_.mark(line_, 1);
    if (!in_block_comment_) {
      const size_t hash = skip_blanks(line, 0);
      if (hash < line.size() && line[hash] == '#') {
        const size_t word_begin = skip_blanks(line, hash + 1);
        size_t word_end = word_begin;
        while (word_end < line.size() && is_ident_char(line[word_end])) ++word_end;
        const std::string_view word = line.substr(word_begin, word_end - word_begin);
        for (const auto& d : kDirectives) {
          if (d.name == word) return run_directive(d.directive, line, hash, word_end);
        }
        if (!word.empty() && !options_.unknown_hash_lines_pass_through) {
          track_comments(line);
          if (active()) report(PreprocError::UnknownDirective, here(hash));
          return;
        }
      }
    }
    if (active()) {
      expand_line(line);
    } else {
      track_comments(line);
    }
  }

  void track_comments(std::string_view line) {
    spans_.clear();
    scan_line(line, options_, in_block_comment_, spans_);
  }

  // --- directives ---------------------------------------------------------------------------

  void run_directive(Directive d, std::string_view line, size_t hash, size_t args_at) {
    // Comments become blanks, so the arguments keep their columns for diagnostics.
    std::string clean(line);
    spans_.clear();
    scan_line(line, options_, in_block_comment_, spans_);
    for (const Span& s : spans_) {
      if (s.kind == SpanKind::Comment)
        std::fill(clean.begin() + s.begin, clean.begin() + s.end, ' ');
    }
    const std::string_view args(clean);
    const Location at = here(hash);
    switch (d) {
      case Directive::Define:
        if (active()) run_define(args, args_at, at);
        break;
      case Directive::Undef:
        if (active()) run_undef(args, args_at, at);
        break;
      case Directive::If:
        open_block(at, [&] { return condition(args, args_at, at); });
        break;
      case Directive::Ifdef:
        open_block(at, [&] { return is_defined(args, args_at, at, true); });
        break;
      case Directive::Ifndef:
        open_block(at, [&] { return is_defined(args, args_at, at, false); });
        break;
      case Directive::Elseif:
        run_elseif(args, args_at, at);
        break;
      case Directive::Else:
        run_else(at);
        break;
      case Directive::Endif:
        run_endif(at);
        break;
      case Directive::Include:
        if (!options_.allow_include)
          extension(false, at);
        else if (active())
          run_include(args, args_at, at);
        break;
      case Directive::Elifdef:
      case Directive::Elifndef:
        if (!options_.allow_elifdef)
          extension(false, at);
        else
          run_branch(at, [&] { return is_defined(args, args_at, at, d == Directive::Elifdef); });
        break;
      case Directive::Definevar:
        extension(options_.allow_definevar, at);
        break;
      case Directive::Information:
        extension(options_.allow_information, at);
        break;
    }
    // A /* comment opened on the directive line goes on below it: keep its opening, or the
    // dialect's lexer would meet its body and its */ without the start.
    if (in_block_comment_ && active() && !spans_.empty() &&
        spans_.back().kind == SpanKind::Comment) {
      out_.mark(line_, static_cast<int>(spans_.back().begin) + 1);
      out_.append(line.substr(spans_.back().begin));
    }
  }

  // #include "file" or <file>: its lines go out in place of the directive's, mapped to it.
  void run_include(std::string_view args, size_t from, const Location& at) {
    const size_t b = skip_blanks(args, from);
    std::string name;
    if (b < args.size() && (args[b] == '"' || args[b] == '<')) {
      const size_t e = args.find(args[b] == '"' ? '"' : '>', b + 1);
      if (e != std::string_view::npos) name = std::string(args.substr(b + 1, e - b - 1));
    }
    if (name.empty())
      return report(PreprocError::IncludeNotFound, here(b),
                    {{at, "#include needs \"file\" or <file>"}});
    if (depth_ >= options_.max_include_depth) {
      return report(PreprocError::IncludeTooDeep, here(b),
                    {{at, "'" + name + "' would be " + std::to_string(depth_ + 1) +
                              " files deep; at most " + std::to_string(options_.max_include_depth) +
                              " (does a file include itself?)"}});
    }
    if (options_.backslash_separates) std::replace(name.begin(), name.end(), '\\', '/');
    const std::filesystem::path given(name);
    const std::filesystem::path dir = std::filesystem::path(source_->name).parent_path();
    std::string path = given.is_absolute() || dir.empty() ? name : (dir / given).string();
    std::string why;
    const auto read_one = [&](const std::string& p) {
      return options_.read_file ? options_.read_file(p, &why) : read_text_file(p, &why);
    };
    std::optional<std::string> text = read_one(path);
    for (size_t f = 0; !text && !given.is_absolute() && f < options_.include_folders.size(); ++f) {
      std::string elsewhere = (std::filesystem::path(options_.include_folders[f]) / given).string();
      std::string first_why = why;
      if ((text = read_one(elsewhere))) {
        path = std::move(elsewhere);
      } else {
        why = std::move(first_why);  // the includer's folder's reason is the one to tell
      }
    }
    if (!text)
      return report(PreprocError::IncludeNotFound, here(b), {{here(b), "'" + path + "': " + why}});
    const SourceFile inner{path, std::move(*text)};
    const SourceFile* outer = source_;
    const int outer_line = line_;
    const bool outer_comment = in_block_comment_;
    const size_t open_blocks = stack_.size();
    const uint32_t outer_file = out_.enter_file(path);
    source_ = &inner;
    in_block_comment_ = false;
    ++depth_;
    run_text();
    // An #if opened in the file closes in it.
    while (stack_.size() > open_blocks) {
      const Location opened = stack_.back().at;
      report(PreprocError::UnterminatedIf, opened,
             {{opened, "this #if has no #endif before the end of its file"}});
      stack_.pop_back();
    }
    --depth_;
    source_ = outer;
    line_ = outer_line;
    in_block_comment_ = outer_comment;
    out_.leave_file(outer_file);
    out_.mark(line_, static_cast<int>(args.size()) + 1);
  }

  void extension(bool allowed, const Location& at) {
    if (!active()) return;
    report(PreprocError::UnknownDirective, at,
           {{at, allowed ? "this directive is not implemented yet"
                         : "this directive is not part of this dialect"}});
  }

  // The first blank-delimited word after the directive: the identifier, valid or not.
  struct Word {
    std::string_view text;
    size_t at;
  };
  static Word word_at(std::string_view args, size_t from) {
    const size_t b = skip_blanks(args, from);
    size_t e = b;
    while (e < args.size() && !is_blank(args[e])) ++e;
    return {args.substr(b, e - b), b};
  }
  bool valid_name(std::string_view name) const {
    if (name.empty() || name.size() > options_.max_name_length) return false;
    if (!is_ident_start(name[0]) || name[0] == '_')
      return false;  // "a name must start with a letter"
    return std::all_of(name.begin(), name.end(), is_ident_char);
  }
  // Reports a missing or invalid name; returns whether the name can be used.
  bool check_name(const Word& w, const Location& directive_at) {
    if (w.text.empty()) {
      report(PreprocError::IdentifierMissing, directive_at);
      return false;
    }
    if (!valid_name(w.text)) {
      report(
          PreprocError::InvalidIdentifier, here(w.at),
          {{here(w.at), "'" + std::string(w.text) +
                            "': a name starts with a letter and holds letters, digits and '_'"}});
      return false;
    }
    return true;
  }

  void run_define(std::string_view args, size_t from, const Location& at) {
    Word name = word_at(args, from);
    std::optional<std::vector<std::string>> params;
    size_t body_at = name.at + name.text.size();
    if (options_.allow_function_macros) {
      // NAME(a, b) body: the parenthesis right after the name makes it function-like.
      size_t e = name.at;
      while (e < args.size() && is_ident_char(args[e])) ++e;
      if (e < args.size() && args[e] == '(') {
        std::vector<std::string> list;
        size_t close = 0;
        if (!read_arguments(args, e, list, close))
          return report(PreprocError::InvalidIdentifier, here(e));
        for (const std::string& p : list) {
          if (!valid_name(p)) return report(PreprocError::InvalidIdentifier, here(e));
        }
        name.text = args.substr(name.at, e - name.at);
        params = std::move(list);
        body_at = close;
      }
    }
    if (!check_name(name, at)) return;
    std::string body(trim(args.substr(std::min(body_at, args.size()))));
    if (const Macro* old = macros_.find(name.text)) {
      if (options_.identical_redefinition_allowed && old->params == params &&
          same_but_whitespace(old->body, body))
        return;
      report(PreprocError::AlreadyDefined, here(name.at),
             {{old->defined_at, "'" + std::string(name.text) + "' was defined here"}});
      return;
    }
    if (define_count_ >= options_.max_defines) {
      report(PreprocError::TooManyDefines, here(name.at));
      return;
    }
    ++define_count_;
    Macro m;
    m.body = std::move(body);
    m.defined_at = at;
    m.params = std::move(params);
    if (!m.body.empty() && !m.params) {
      // Manual 2.9.1: a string that evaluates is replaced by its value, any other by itself.
      const EvalResult r =
          evaluate_constant(m.body, [this](std::string_view n) { return value_of(n); });
      if (r.status == EvalStatus::Ok) m.value = r.value;
    }
    macros_.define(std::string(name.text), std::move(m));
    expander_.forget_failures();
  }

  void run_undef(std::string_view args, size_t from, const Location& at) {
    const Word name = word_at(args, from);
    if (!check_name(name, at)) return;
    if (!macros_.undefine(name.text)) {
      if (options_.undef_of_undefined_ignored) return;
      return report(PreprocError::NotDefined, here(name.at),
                    {{here(name.at), "'" + std::string(name.text) + "' is not defined"}});
    }
    expander_.forget_failures();
  }

  std::optional<TypedValue> value_of(std::string_view name) const {
    const Macro* m = macros_.find(name);
    if (m) return m->value;
    return std::nullopt;
  }

  // #if's and #elseif's condition; false after an error, so the branch is skipped.
  bool condition(std::string_view args, size_t from, const Location& at) {
    const std::string_view expr = args.substr(std::min(from, args.size()));
    const EvalResult r =
        evaluate_constant(expr, [this](std::string_view n) -> std::optional<TypedValue> {
          if (const Macro* m = macros_.find(n); m && m->value) return m->value;
          if (std::optional<int32_t> v;
              !macros_.find(n) && options_.predefined && options_.predefined(n, v, line_) && v)
            return TypedValue::of_int(*v);
          if (options_.undefined_identifier_is_zero && !macros_.find(n))
            return TypedValue::of_int(0);
          return std::nullopt;
        });
    const Location where = here(from + r.error_at);
    switch (r.status) {
      case EvalStatus::Ok:
        return is_true(r.value);
      case EvalStatus::Empty:
        report(PreprocError::ConditionMissing, at);
        break;
      case EvalStatus::DivisionByZero:
        report(PreprocError::DivisionByZero, where);
        break;
      default:
        report(PreprocError::MismatchedType, where, {{where, r.detail}});
        break;
    }
    return false;
  }

  bool is_defined(std::string_view args, size_t from, const Location& at, bool want_defined) {
    const Word name = word_at(args, from);
    if (!check_name(name, at)) return false;
    const Word extra = word_at(args, name.at + name.text.size());
    if (!extra.text.empty()) {
      report(PreprocError::InvalidIdentifier, here(extra.at),
             {{here(extra.at), "only one identifier may follow #ifdef or #ifndef"}});
      return false;
    }
    std::optional<int32_t> value;
    const bool known = macros_.find(name.text) != nullptr ||
                       (options_.predefined && options_.predefined(name.text, value, line_));
    return known == want_defined;
  }

  template <class Condition>
  void open_block(const Location& at, Condition cond) {
    if (!active()) {
      // A skipped block's nested directives only keep the nesting; nothing is evaluated.
      stack_.push_back({at, false, false, true, false, 0});
      return;
    }
    const bool keep = cond();
    stack_.push_back({at, true, keep, keep, false, 0});
  }

  void run_elseif(std::string_view args, size_t from, const Location& at) {
    run_branch(at, [&] { return condition(args, from, at); });
  }

  // #elseif, #elifdef, #elifndef: the next branch, taken when none was and `cond` holds.
  template <class Condition>
  void run_branch(const Location& at, Condition cond) {
    if (stack_.empty()) return report(PreprocError::MisplacedElse, at);
    Conditional& c = stack_.back();
    if (c.seen_else) {
      c.active = false;
      return report(PreprocError::MisplacedElse, at,
                    {{c.at, "#else must be the last directive before #endif"}});
    }
    if (++c.elseifs > options_.max_elseifs) {
      c.active = false;
      return report(PreprocError::TooManyElseifs, at,
                    {{at, "more than " + std::to_string(options_.max_elseifs) +
                              " #elseif directives in one #if block"}});
    }
    if (!c.parent_active || c.taken) {
      c.active = false;
      return;
    }
    c.active = cond();
    c.taken = c.active;
  }

  void run_else(const Location& at) {
    if (stack_.empty()) return report(PreprocError::MisplacedElse, at);
    Conditional& c = stack_.back();
    if (c.seen_else) {
      c.active = false;
      return report(PreprocError::MisplacedElse, at, {{c.at, "this #if already has an #else"}});
    }
    c.seen_else = true;
    c.active = c.parent_active && !c.taken;
    c.taken = true;
  }

  void run_endif(const Location& at) {
    if (stack_.empty()) return report(PreprocError::MisplacedEndif, at);
    stack_.pop_back();
  }

  // --- expansion ----------------------------------------------------------------------------

  void expand_line(std::string_view line) {
    if (macros_.empty()) {
      // Nothing to replace: the line goes out as it is. Only a '/' can open a block comment
      // (all comment markers but `**` start with it), and only its state must be followed.
      if (in_block_comment_ || line.find('/') != std::string_view::npos) track_comments(line);
      out_.append(line);
      return;
    }
    std::vector<Span>& spans = spans_;
    spans.clear();
    scan_line(line, options_, in_block_comment_, spans);
    size_t skip_to = 0;  // a function-like use's arguments go with it
    for (const Span& s : spans) {
      if (s.begin < skip_to) {
        if (s.end > skip_to) out_.append(line.substr(skip_to, s.end - skip_to));
        continue;
      }
      const std::string_view piece = line.substr(s.begin, s.end - s.begin);
      const Macro* m = s.kind == SpanKind::Identifier ? macros_.find(piece) : nullptr;
      std::vector<std::string> args;
      size_t end = s.end;
      if (!Expander::expands(m) || (m->params && !read_arguments(line, s.end, args, end))) {
        out_.append(piece);
        continue;
      }
      expand_use(piece, *m, here(s.begin), m->params ? &args : nullptr);
      skip_to = end;
      out_.mark(line_, static_cast<int>(end) + 1);
    }
  }

  void expand_use(std::string_view name, const Macro& m, const Location& used_at,
                  const std::vector<std::string>* args = nullptr) {
    const std::optional<std::string> text = expander_.expand(name, m, args);
    if (!text) {
      report(PreprocError::ExpansionTooComplex, used_at,
             {{m.defined_at, "expanding '" + std::string(name) + "' goes too deep or too long"}});
      out_.append(name);
      return;
    }
    const size_t begin = out_.size();
    out_.append(*text);
    out_.add_expansion({begin, out_.size(), std::string(name), used_at, m.defined_at});
  }

  const SourceFile* source_;  // the file being read: the source or an #include'd one
  const PreprocOptions& options_;
  DiagnosticList& diagnostics_;
  OutputBuilder out_;
  MacroTable macros_;
  std::vector<Conditional> stack_;
  std::vector<Span> spans_;
  int line_ = 1;
  int define_count_ = 0;
  int depth_ = 0;  // #include nesting
  bool in_block_comment_ = false;
  Expander expander_{macros_, options_};
};

}  // namespace

Preprocessed preprocess(const SourceFile& source, const PreprocOptions& options,
                        DiagnosticList& diagnostics) {
  return Preprocessor(source, options, diagnostics).run();
}

}  // namespace uprog::preproc
