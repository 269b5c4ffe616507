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

std::optional<std::string> Expander::expand(std::string_view name, const Macro& m) {
  const bool known_failure = std::find(too_complex_.begin(), too_complex_.end(), name) != too_complex_.end();
  bool ok = !known_failure && total_expanded_ < kMaxTotalExpansionChars;
  std::string text;
  if (ok && m.value) {
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
  for (const Span& s : spans) {
    const std::string_view piece = body.substr(s.begin, s.end - s.begin);
    const Macro* m = s.kind == SpanKind::Identifier ? macros_.find(piece) : nullptr;
    if (!expands(m) || std::find(painted.begin(), painted.end(), piece) != painted.end()) {
      text.append(piece);
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
