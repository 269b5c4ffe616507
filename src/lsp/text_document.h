// An open document as the editor holds it: its text, version and dialect, the LSP positions in
// it (line and character, the character counted in UTF-16 code units or UTF-8 bytes as the
// client and server agreed), and the edits didChange sends.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace uprog::dialect {
class Dialect;
}

namespace uprog::lsp {

enum class PositionEncoding : uint8_t { Utf16, Utf8 };

struct Position {
  int64_t line = 0;       // 0-based
  int64_t character = 0;  // 0-based, in the agreed encoding
};

// The byte offset of `p` in `text`; a character past its line's end is the line's end, a line
// past the text's end the text's end (LSP 3.17: positions are clamped to the line).
size_t offset_of(std::string_view text, Position p, PositionEncoding encoding);
// The position of byte `offset` of `text`.
Position position_of(std::string_view text, size_t offset, PositionEncoding encoding);
// The byte offset where 0-based line `line` starts (the text's size past its end).
size_t line_start(std::string_view text, int64_t line);

struct TextDocument {
  std::string uri;
  std::string path;  // the file the URI names ("" for another scheme): includes resolve from it
  std::string language_id;
  const dialect::Dialect* dialect = nullptr;  // nullptr: no dialect takes it, nothing to check
  int64_t version = 0;
  std::string text;

  // Replaces [start, end) with `replacement`; a range past the text is clamped to it.
  void replace(Position start, Position end, std::string_view replacement,
               PositionEncoding encoding);
};

}  // namespace uprog::lsp
