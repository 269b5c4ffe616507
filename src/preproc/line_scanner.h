// Splits a line of source into the stretches the preprocessor must tell apart: code, identifiers
// that may be macros, comments and strings, where identifiers are never replaced (manual 2.9.1).
#pragma once
#include <cstddef>
#include <string_view>
#include <vector>

#include "preproc/preprocess.h"

namespace uprog::preproc {

enum class SpanKind { Code, Identifier, Comment, String };

struct Span {
  SpanKind kind;
  size_t begin, end;  // offsets in the line, [begin, end)
};

inline bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }
inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// Appends the spans of `line` (without its '\n') to `out`. `in_block_comment` says whether the
// line starts inside a /* */ comment and, on return, whether it ends inside one.
// Identifiers inside numbers (0xABC, 2PI) and label names after `##` or `#@` are Code.
void scan_line(std::string_view line, const PreprocOptions& options, bool& in_block_comment,
               std::vector<Span>& out);

}  // namespace uprog::preproc
