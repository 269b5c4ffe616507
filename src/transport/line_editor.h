// The host's typing side of a terminal: libedit's line editing and history when stdin is a
// terminal, plain line reads when it is a pipe (scripts, tests).
#pragma once
#include <optional>
#include <string>

namespace uprog::transport {

class LineEditor {
 public:
  // `history_file` ("" for none) is read now and written back when the editor goes away.
  explicit LineEditor(std::string history_file);
  ~LineEditor();
  LineEditor(const LineEditor&) = delete;
  LineEditor& operator=(const LineEditor&) = delete;

  bool interactive() const { return interactive_; }
  // The next line without its newline; nullopt at end of input (Ctrl-D, end of the pipe).
  std::optional<std::string> read_line(const char* prompt);

 private:
  std::string history_file_;
  bool interactive_ = false;
};

}  // namespace uprog::transport
