// The host's side of the semicolon wire (dialect/semicolon_wire.h): splits what the drive sends
// into answers (each ends with `;`) and end-of-line marks (CR LF after the answers to one typed
// line). Used by `uprog term`, `uprog download` and tests.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/semicolon_wire.h"
#include "dialect/wire_form.h"
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
  // Reads a prompting drive's wire (dialect::PromptWire) instead of the semicolon wire: a line
  // per answer, an error by its prefix, the prompt ends a line's answers.
  void read_prompts(const dialect::PromptWire& wire) { prompt_ = wire; }
  // The line just sent, whose echo (the first line to come back, if it is that line) is dropped.
  void expect_echo(std::string_view line) { echo_ = line; }
  void feed(std::string_view bytes, std::vector<AnswerEvent>& out);
  // Text received after the last `;` or CR LF (an answer still arriving).
  const std::string& partial() const { return partial_; }

 private:
  void feed_prompted(char c, std::vector<AnswerEvent>& out);

  std::string partial_;
  bool after_cr_ = false;
  std::optional<dialect::PromptWire> prompt_;
  std::optional<std::string> echo_;
};

}  // namespace uprog::transport
