// Splits the drive's byte stream into answers and end-of-line marks (answer_reader.h).
#include "transport/answer_reader.h"

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

void AnswerReader::feed(std::string_view bytes, std::vector<AnswerEvent>& out) {
  for (const char c : bytes) {
    const bool was_after_cr = after_cr_;
    after_cr_ = c == '\r';
    if (c == ';') {
      out.push_back({false, parse_answer(partial_)});
      partial_.clear();
    } else if (c == '\r' || c == '\n') {
      if (c == '\n' && was_after_cr) continue;  // the LF of CR LF
      // Text ended by a line break rather than `;` is the drive's own output, not an answer.
      if (partial_.empty()) out.push_back({true, {}, false});
      else out.push_back({false, {partial_, 0}, true});
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
