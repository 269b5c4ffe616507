// The host's side of the semicolon wire (dialect/semicolon_wire.h): splits what the drive sends
// into answers (each ends with `;`) and end-of-line marks (CR LF after the answers to one typed
// line). Used by `uprog term`, `uprog download` and tests.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "dialect/semicolon_wire.h"
#include "transport/reply.h"

namespace uprog::transport {

struct AnswerEvent {
  bool end_of_line = false;  // true: all answers to one physical line have come; reply unused
  Reply reply;
  // True: a line the drive sent on its own (a program's message), its text in reply.text; it is
  // no answer to any line the host sent.
  bool output = false;
};

class AnswerReader {
 public:
  void feed(std::string_view bytes, std::vector<AnswerEvent>& out);
  // Text received after the last `;` or CR LF (an answer still arriving).
  const std::string& partial() const { return partial_; }

 private:
  std::string partial_;
  bool after_cr_ = false;
};

}  // namespace uprog::transport
