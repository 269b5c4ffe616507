// Splits the bytes a host sends into command lines, the way a dialect's drive reads them (its
// WireForm's FramerOptions): a line ends with CR, LF and, where the dialect says, `;`; a comment
// marker runs to CR/LF; a line has a bounded length. Pure: no I/O. The transports and the
// firmwares' own line splitting share it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace uprog::dialect {

// Each dialect's WireForm gives its own; these defaults only end lines at CR and LF.
struct FramerOptions {
  std::size_t max_line_length = 255;     // characters of one line, comments excluded
  bool semicolon_ends_line = false;      // `;` ends a line, as CR and LF do
  std::string_view comment_marker = "";  // the rest of the physical line is ignored; "" for none
  // An empty expression ended by `;`, CR or a lone LF is a line of its own (kLine with no text), as
  // a real Elmo drive answers it; LF right after CR ends nothing. False: blank lines are dropped.
  bool answer_empty_expressions = false;
  // An empty physical line (CR or a lone LF) still ends with a kLineBreak, so a drive that
  // prompts gives its prompt again (the S300: a host sends CR and waits for `-->`); the LF of a
  // CR LF ends nothing.
  bool break_empty_lines = false;
};

// One thing the framer recognised in the byte stream.
struct Frame {
  enum class Kind : std::uint8_t {
    kLine,          // a complete, non-blank line (text trimmed of surrounding blanks)
    kTooLong,       // a line longer than max_line_length ended; its bytes were dropped
    kBadCharacter,  // a line with a control or non-ASCII byte (NUL, ESC, 0x80-0xFF) ended
    kLineBreak,     // CR or LF ended a physical line that held something other than blanks
  };
  Kind kind = Kind::kLine;
  std::string text;  // kLine only

  friend bool operator==(const Frame&, const Frame&) = default;
};

// Feed bytes in any chunking; complete frames come out in order. Memory stays bounded by
// max_line_length whatever arrives. Backspace (0x08) and DEL (0x7f) erase the previous character,
// so a person typing into a raw serial terminal can correct a line.
class LineFramer {
 public:
  explicit LineFramer(FramerOptions options = {});

  void feed(std::string_view bytes, std::vector<Frame>& out);
  // Drops a partial line (the host went away mid-line).
  void reset();
  // Bytes of the current, unterminated line held so far.
  std::size_t pending_size() const { return line_.size(); }

 private:
  void end_expression(std::vector<Frame>& out);
  void add_character(char c);

  FramerOptions options_;
  std::string line_;
  bool too_long_ = false;
  bool bad_character_ = false;
  bool in_comment_ = false;
  bool physical_line_has_content_ = false;
  bool after_cr_ = false;
  std::size_t marker_matched_ = 0;  // characters of the comment marker seen at the end of line_
};

// The lines of one complete text (a transcript's or a console's line): its frames without the
// line-break marks, the last line ended even without CR or LF.
std::vector<Frame> frame_text(std::string_view text, const FramerOptions& options);

}  // namespace uprog::dialect
