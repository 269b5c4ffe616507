// Taking a drive's echo out of its answers (echo_filter.h).
#include "transport/echo_filter.h"

namespace uprog::transport {

void EchoFilter::expect(std::string_view sent, std::string_view ends) {
  pieces_.clear();
  std::string piece;
  for (const char c : sent) {
    piece.push_back(c);
    if (ends.find(c) != std::string_view::npos) pieces_.push_back(std::move(piece)), piece.clear();
  }
  if (!piece.empty()) pieces_.push_back(std::move(piece));
  piece_ = 0;
  matched_ = 0;
  in_answer_ = false;
  held_.clear();
}

void EchoFilter::feed(std::string_view bytes, std::string& out) {
  for (const char c : bytes) {
    if (piece_ >= pieces_.size()) {
      out.push_back(c);
      continue;
    }
    if (in_answer_) {
      out.push_back(c);
      // The piece's answer ends with `;`; the next piece's echo follows.
      if (c == ';') ++piece_, in_answer_ = false;
      continue;
    }
    const std::string& expected = pieces_[piece_];
    if (c == expected[matched_]) {
      held_.push_back(c);
      if (++matched_ == expected.size()) {
        echo_seen_ = true;
        held_.clear();
        matched_ = 0;
        in_answer_ = true;
      }
      continue;
    }
    // Not the echo: the drive does not echo (any more); what was held is its answer.
    echo_seen_ = false;
    out += held_;
    out.push_back(c);
    held_.clear();
    pieces_.clear();
  }
}

}  // namespace uprog::transport
