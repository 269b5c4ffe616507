// The host's side of a drive that echoes (a real Elmo drive while EO=1): takes the echo of the
// line just sent out of what the drive sends back, so that only answers remain. The drive echoes
// each expression's bytes before it answers that expression, so echo and answers interleave:
// `PX;MO\r` comes back as `PX;` `1234;` `MO\r` `1;`. Whether the drive echoes is learnt from the
// first bytes after each line (they either repeat the line or start an answer).
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace uprog::transport {

class EchoFilter {
 public:
  // The bytes of the line just sent; `ends` are its expression terminators (`;` where the
  // dialect ends an expression with it, CR, LF).
  void expect(std::string_view sent, std::string_view ends);
  // Bytes from the drive in; appends them to `out` without the echo.
  void feed(std::string_view bytes, std::string& out);
  // What the last line showed: true when the drive echoed it.
  bool echo_seen() const { return echo_seen_; }

 private:
  std::vector<std::string> pieces_;  // the sent line cut after each terminator
  std::size_t piece_ = 0;            // the piece whose echo (or answer) comes next
  std::size_t matched_ = 0;          // bytes of that piece's echo seen so far
  bool in_answer_ = false;           // the piece's echo came; its answer is arriving
  std::string held_;                 // bytes that may be echo, not yet passed on
  bool echo_seen_ = false;
};

}  // namespace uprog::transport
