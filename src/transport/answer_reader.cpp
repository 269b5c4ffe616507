// Splits the drive's byte stream into answers and end-of-line marks (answer_reader.h).
#include "transport/answer_reader.h"

#include <utility>

namespace uprog::transport {

namespace {

constexpr std::size_t kMaxAnswer = 1 << 16;  // a longer answer is delivered in pieces

// Either wire form: the readable `?CODE TEXT`, or a drive's `<code byte>?` (MAN-SIMSW 3.1).
Reply parse_answer(std::string_view answer) {
  if (answer.size() == 2 && answer.back() == '?' && answer.front() != '?') {
    return {"", static_cast<unsigned char>(answer.front())};
  }
  return dialect::parse_semicolon_answer(answer);
}

}  // namespace

// A prompting drive: each CR LF ends an answer (the echo of the line sent is dropped, an error
// is `prefix code text`); the prompt, arriving without a line end, ends the line's answers.
void AnswerReader::feed_prompted(char c, std::vector<AnswerEvent>& out) {
  if (c == '\n') return;
  if (c != '\r') {
    partial_.push_back(c);
    if (partial_ == prompt_->prompt) {
      echo_.reset();
      partial_.clear();
      out.push_back({true, {}, false});
    }
    return;
  }
  std::string line = std::exchange(partial_, std::string());
  if (echo_) {
    const bool is_echo = line == *echo_;
    echo_.reset();
    if (is_echo) return;
  }
  const std::string& prefix = prompt_->error_prefix;
  if (!prefix.empty() && line.starts_with(prefix)) {
    std::string_view rest = std::string_view(line).substr(prefix.size());
    int32_t code = 0;
    size_t digits = 0;
    for (; digits < rest.size() && digits < 9 && rest[digits] >= '0' && rest[digits] <= '9';
         ++digits)
      code = code * 10 + (rest[digits] - '0');
    rest.remove_prefix(digits);
    if (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    out.push_back({false, {std::string(rest), code == 0 ? 1 : code}});
    return;
  }
  out.push_back({false, {std::move(line), 0}});
}

void AnswerReader::feed(std::string_view bytes, std::vector<AnswerEvent>& out) {
  if (prompt_) {
    for (const char c : bytes) feed_prompted(c, out);
    return;
  }
  for (const char c : bytes) {
    const bool was_after_cr = after_cr_;
    after_cr_ = c == '\r';
    if (c == ';') {
      out.push_back({false, parse_answer(partial_)});
      partial_.clear();
    } else if (c == '\r' || c == '\n') {
      if (c == '\n' && was_after_cr) continue;  // the LF of CR LF
      // Text ended by a line break rather than `;` is the drive's own output, not an answer.
      if (partial_.empty())
        out.push_back({true, {}, false});
      else
        out.push_back({false, {partial_, 0}, true});
      partial_.clear();
    } else {
      partial_.push_back(c);
      if (partial_.size() >= kMaxAnswer) {
        out.push_back({false, parse_answer(partial_)});
        partial_.clear();
      }
    }
  }
}

}  // namespace uprog::transport
