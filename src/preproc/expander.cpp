// Macro replacement with C's rule that a name is not expanded inside its own expansion, so
// `#define A A` and A -> B -> A end; depth and length limits catch what that rule does not.
#include "preproc/expander.h"

#include <algorithm>

#include "preproc/const_expr.h"
#include "preproc/line_scanner.h"

namespace uprog::preproc {
namespace {

// Caps the sum of all expansions in one file, so a line of a million uses of a large macro
// cannot make the output explode.
constexpr size_t kMaxTotalExpansionChars = size_t{1} << 24;

}  // namespace

bool read_arguments(std::string_view text, size_t pos, std::vector<std::string>& args,
                    size_t& end) {
  while (pos < text.size() && is_blank(text[pos])) ++pos;
  if (pos >= text.size() || text[pos] != '(') return false;
  args.clear();
  std::string current;
  int depth = 0;
  char quote = 0;
  for (size_t i = pos + 1; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '(') {
      ++depth;
    } else if (c == ')' && depth > 0) {
      --depth;
    } else if ((c == ')' || c == ',') && depth == 0) {
      size_t b = 0, e = current.size();
      while (b < e && is_blank(current[b])) ++b;
      while (e > b && is_blank(current[e - 1])) --e;
      args.push_back(current.substr(b, e - b));
      current.clear();
      if (c == ')') {
        end = i + 1;
        if (args.size() == 1 && args[0].empty()) args.clear();  // F()
        return true;
      }
      continue;
    }
    current.push_back(c);
  }
  return false;
}

std::string substitute(const Macro& m, const std::vector<std::string>& args,
                       const PreprocOptions& options) {
  bool in_comment = false;
  std::vector<Span> spans;
  scan_line(m.body, options, in_comment, spans);
  std::string out;
  for (const Span& s : spans) {
    const std::string_view piece = std::string_view(m.body).substr(s.begin, s.end - s.begin);
    const auto& params = *m.params;
    const auto it = s.kind == SpanKind::Identifier ? std::find(params.begin(), params.end(), piece)
                                                   : params.end();
    if (it != params.end() && static_cast<size_t>(it - params.begin()) < args.size()) {
      out += args[static_cast<size_t>(it - params.begin())];
    } else {
      out.append(piece);
    }
  }
  return out;
}

std::optional<std::string> Expander::expand(std::string_view name, const Macro& m,
                                            const std::vector<std::string>* args) {
  const bool known_failure =
      std::find(too_complex_.begin(), too_complex_.end(), name) != too_complex_.end();
  bool ok = !known_failure && total_expanded_ < kMaxTotalExpansionChars;
  std::string text;
  if (ok && m.params) {
    std::vector<std::string_view> painted{name};
    const std::string body = substitute(m, args ? *args : std::vector<std::string>{}, options_);
    ok = expand_body(body, painted, 1, text);
  } else if (ok && m.value) {
    text = format_constant(*m.value);
  } else if (ok) {
    std::vector<std::string_view> painted{name};
    ok = expand_body(m.body, painted, 1, text);
  }
  if (!ok) {
    // Until the table changes this name fails the same way; remembering it keeps a file of
    // many such uses linear.
    if (!known_failure) too_complex_.emplace_back(name);
    return std::nullopt;
  }
  total_expanded_ += text.size();
  return text;
}

bool Expander::expand_body(std::string_view body, std::vector<std::string_view>& painted, int depth,
                           std::string& text) const {
  if (depth > options_.max_expansion_depth) return false;
  bool in_comment = false;
  std::vector<Span> spans;
  scan_line(body, options_, in_comment, spans);
  size_t skip_to = 0;  // a function-like use's arguments are consumed with it
  for (const Span& s : spans) {
    if (s.begin < skip_to) {
      if (s.end > skip_to) text.append(body.substr(skip_to, s.end - skip_to));
      continue;
    }
    const std::string_view piece = body.substr(s.begin, s.end - s.begin);
    const Macro* m = s.kind == SpanKind::Identifier ? macros_.find(piece) : nullptr;
    std::vector<std::string> args;
    size_t end = 0;
    if (!expands(m) || std::find(painted.begin(), painted.end(), piece) != painted.end() ||
        (m->params && !read_arguments(body, s.end, args, end))) {
      text.append(piece);
    } else if (m->params) {
      painted.push_back(piece);
      if (!expand_body(substitute(*m, args, options_), painted, depth + 1, text)) return false;
      painted.pop_back();
      skip_to = end;
    } else if (m->value) {
      text.append(format_constant(*m->value));
    } else {
      painted.push_back(piece);
      if (!expand_body(m->body, painted, depth + 1, text)) return false;
      painted.pop_back();
    }
    if (text.size() > options_.max_expansion_chars) return false;
  }
  return true;
}

}  // namespace uprog::preproc
