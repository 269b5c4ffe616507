// One pass over a line, character by character, so any byte sequence takes linear time.
#include "preproc/line_scanner.h"

namespace uprog::preproc {
namespace {

void push(std::vector<Span>& out, SpanKind kind, size_t begin, size_t end) {
  if (begin == end) return;
  if (!out.empty() && out.back().kind == kind && kind == SpanKind::Code &&
      out.back().end == begin) {
    out.back().end = end;  // adjacent code merges, so callers copy longer runs
    return;
  }
  out.push_back({kind, begin, end});
}

}  // namespace

void scan_line(std::string_view line, const PreprocOptions& options, bool& in_block_comment,
               std::vector<Span>& out) {
  const size_t n = line.size();
  size_t i = 0;
  auto at = [&](size_t k) { return k < n ? line[k] : '\0'; };
  while (i < n) {
    if (in_block_comment) {
      const size_t close = line.find("*/", i);
      const size_t end = close == std::string_view::npos ? n : close + 2;
      if (close != std::string_view::npos) in_block_comment = false;
      push(out, SpanKind::Comment, i, end);
      i = end;
      continue;
    }
    const char c = line[i];
    if ((options.slash_slash_comments && c == '/' && at(i + 1) == '/') ||
        (options.star_star_comments && c == '*' && at(i + 1) == '*')) {
      push(out, SpanKind::Comment, i, n);
      return;
    }
    if (options.block_comments && c == '/' && at(i + 1) == '*') {
      in_block_comment = true;
      push(out, SpanKind::Comment, i, i + 2);
      i += 2;
      // The comment's body joins this span in the next round.
      const size_t close = line.find("*/", i);
      const size_t end = close == std::string_view::npos ? n : close + 2;
      if (close != std::string_view::npos) in_block_comment = false;
      out.back().end = end;
      i = end;
      continue;
    }
    if (options.string_quote != 0 && c == options.string_quote) {
      const size_t close = line.find(options.string_quote, i + 1);
      const size_t end =
          close == std::string_view::npos ? n : close + 1;  // strings end with the line
      push(out, SpanKind::String, i, end);
      i = end;
      continue;
    }
    if (is_digit(c) || (c == '.' && is_digit(at(i + 1)))) {
      size_t j = i + 1;
      while (j < n && (is_ident_char(line[j]) || line[j] == '.')) ++j;
      push(out, SpanKind::Code, i, j);
      i = j;
      continue;
    }
    if (is_ident_start(c)) {
      size_t j = i + 1;
      while (j < n && is_ident_char(line[j])) ++j;
      const bool label = i >= 2 && line[i - 2] == '#' && (line[i - 1] == '#' || line[i - 1] == '@');
      push(out, label ? SpanKind::Code : SpanKind::Identifier, i, j);
      i = j;
      continue;
    }
    push(out, SpanKind::Code, i, i + 1);
    ++i;
  }
}

}  // namespace uprog::preproc
