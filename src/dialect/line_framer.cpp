// The line framer: bytes in, command lines and framing errors out (see line_framer.h).
#include "dialect/line_framer.h"

namespace uprog::dialect {

namespace {

constexpr char kBackspace = 0x08;
constexpr char kDelete = 0x7f;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

bool is_printable(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return (byte >= 0x20 && byte < 0x7f) || c == '\t';
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace

LineFramer::LineFramer(FramerOptions options) : options_(options) {
  line_.reserve(options_.max_line_length);
}

void LineFramer::reset() {
  line_.clear();
  too_long_ = false;
  bad_character_ = false;
  in_comment_ = false;
  physical_line_has_content_ = false;
  after_cr_ = false;
  marker_matched_ = 0;
}

void LineFramer::feed(std::string_view bytes, std::vector<Frame>& out) {
  for (const char c : bytes) {
    const bool lf_of_cr_lf = c == '\n' && after_cr_;
    after_cr_ = c == '\r';
    if (lf_of_cr_lf && options_.answer_empty_expressions) continue;
    if (c == '\r' || c == '\n') {
      end_expression(out);
      in_comment_ = false;
      if (physical_line_has_content_ || (options_.break_empty_lines && !lf_of_cr_lf))
        out.push_back({Frame::Kind::kLineBreak, {}});
      physical_line_has_content_ = false;
      continue;
    }
    if (!is_blank(c)) physical_line_has_content_ = true;
    if (in_comment_) continue;  // everything up to CR/LF, `;` and binary bytes included
    if (c == ';' && options_.semicolon_ends_line) {
      end_expression(out);
      continue;
    }
    add_character(c);
  }
}

std::vector<Frame> frame_text(std::string_view text, const FramerOptions& options) {
  LineFramer framer(options);
  std::vector<Frame> frames;
  framer.feed(text, frames);
  framer.feed("\n", frames);
  std::erase_if(frames, [](const Frame& f) { return f.kind == Frame::Kind::kLineBreak; });
  return frames;
}

void LineFramer::add_character(char c) {
  if (c == kBackspace || c == kDelete) {
    if (!line_.empty() && !too_long_) line_.pop_back();
    marker_matched_ = 0;
    return;
  }
  if (!is_printable(c)) {
    bad_character_ = true;
    marker_matched_ = 0;
    return;
  }
  const auto marker = options_.comment_marker;
  if (!marker.empty()) {
    marker_matched_ = c == marker[marker_matched_] ? marker_matched_ + 1 : c == marker[0] ? 1 : 0;
    if (marker_matched_ == marker.size()) {
      // The marker's earlier characters are already in the line: take them out again.
      const std::size_t held = std::min(marker.size() - 1, line_.size());
      line_.resize(line_.size() - held);
      in_comment_ = true;
      marker_matched_ = 0;
      return;
    }
  }
  if (too_long_) return;
  if (line_.empty() && is_blank(c)) return;  // leading blanks do not count toward the limit
  if (line_.size() >= options_.max_line_length) {
    too_long_ = true;
    line_.clear();
    return;
  }
  line_.push_back(c);
}

void LineFramer::end_expression(std::vector<Frame>& out) {
  if (too_long_) {
    out.push_back({Frame::Kind::kTooLong, {}});
  } else if (bad_character_) {
    out.push_back({Frame::Kind::kBadCharacter, {}});
  } else if (const auto text = trim(line_);
             !text.empty() || (options_.answer_empty_expressions && !in_comment_)) {
    out.push_back({Frame::Kind::kLine, std::string(text)});
  }
  line_.clear();
  too_long_ = false;
  bad_character_ = false;
  marker_matched_ = 0;
}

}  // namespace uprog::dialect
