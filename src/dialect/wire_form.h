// How a dialect's drive talks on the wire: how the bytes a host sends are cut into lines, and how
// answers, the end of a typed line and unsolicited output are written back. The transports ask
// the controller's firmware for its WireForm and know no dialect's syntax.
#pragma once
#include <string>
#include <string_view>

#include "dialect/answer.h"
#include "dialect/line_framer.h"

namespace uprog::dialect {

class WireForm {
 public:
  virtual ~WireForm() = default;
  virtual FramerOptions framing() const = 0;
  // Appends one answer to a line.
  virtual void write_answer(const Answer& answer, std::string& out) const = 0;
  // Appends what a line that gave no answer gets, so a host still sees the line was taken.
  virtual void write_silent_line(std::string& out) const = 0;
  // Appends what follows the answers to one physical line (CR LF, a prompt).
  virtual void write_line_end(std::string& out) const = 0;
  // Appends text the drive sends on its own (a program's message); it starts and ends a line.
  virtual void write_output(std::string_view text, std::string& out) const = 0;
};

}  // namespace uprog::dialect
