// Positions and edits in an open document (text_document.h).
#include "lsp/text_document.h"

#include <algorithm>

namespace uprog::lsp {
namespace {

// The bytes of the UTF-8 sequence that starts with `lead` (1 for a stray continuation byte,
// which counts as one character as an invalid byte does in an editor).
size_t sequence_length(unsigned char lead) {
  if (lead >= 0xF0 && lead <= 0xF7) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

size_t line_end(std::string_view text, size_t start) {
  const size_t nl = text.find('\n', start);
  size_t end = nl == std::string_view::npos ? text.size() : nl;
  if (end > start && text[end - 1] == '\r') --end;
  return end;
}

}  // namespace

size_t line_start(std::string_view text, int64_t line) {
  size_t at = 0;
  for (int64_t l = 0; l < line; ++l) {
    const size_t nl = text.find('\n', at);
    if (nl == std::string_view::npos) return text.size();
    at = nl + 1;
  }
  return at;
}

size_t offset_of(std::string_view text, Position p, PositionEncoding encoding) {
  if (p.line < 0) return 0;
  const size_t start = line_start(text, p.line);
  const size_t end = line_end(text, start);
  size_t at = start;
  int64_t units = 0;
  while (at < end && units < p.character) {
    const size_t n = std::min(sequence_length(static_cast<unsigned char>(text[at])), end - at);
    // A character above U+FFFF is two UTF-16 units (a surrogate pair).
    units += encoding == PositionEncoding::Utf8 ? static_cast<int64_t>(n) : (n == 4 ? 2 : 1);
    at += n;
  }
  return at;
}

Position position_of(std::string_view text, size_t offset, PositionEncoding encoding) {
  offset = std::min(offset, text.size());
  Position p;
  size_t start = 0;
  for (size_t nl = text.find('\n'); nl != std::string_view::npos && nl < offset;
       nl = text.find('\n', start)) {
    ++p.line;
    start = nl + 1;
  }
  for (size_t at = start; at < offset;) {
    const size_t n = std::min(sequence_length(static_cast<unsigned char>(text[at])), offset - at);
    p.character += encoding == PositionEncoding::Utf8 ? static_cast<int64_t>(n) : (n == 4 ? 2 : 1);
    at += n;
  }
  return p;
}

void TextDocument::replace(Position start, Position end, std::string_view replacement,
                           PositionEncoding encoding) {
  const size_t from = offset_of(text, start, encoding);
  const size_t to = std::max(from, offset_of(text, end, encoding));
  text.replace(from, to - from, replacement);
}

}  // namespace uprog::lsp
