// The S300 wire form (wire.h).
#include "dialects/st/wire.h"

namespace uprog::st {

dialect::FramerOptions framing_options() {
  dialect::FramerOptions o;
  o.max_line_length = 255;
  return o;
}

S300Wire::S300Wire(const int32_t& prompt, dialect::WireStyle style)
    : prompt_(prompt), style_(style), readable_(framing_options()) {}

dialect::FramerOptions S300Wire::framing() const { return framing_options(); }

std::string answer_text(const dialect::Answer& a) {
  if (a.error == 0) return a.text;
  return "\aERR " + std::to_string(a.error) + (a.text.empty() ? "" : " " + a.text);
}

void S300Wire::write_answer(const dialect::Answer& a, std::string& out) const {
  if (!drive_style()) return readable_.write_answer(a, out);
  for (char c : answer_text(a)) out.push_back(c == '\r' || c == '\n' ? ' ' : c);
  out += "\r\n";
}

// The drive answers a write with nothing; the readable form marks it, as every uprog drive does.
void S300Wire::write_silent_line(std::string& out) const {
  if (!drive_style()) readable_.write_silent_line(out);
}

void S300Wire::write_line_end(std::string& out) const {
  if (!drive_style()) return readable_.write_line_end(out);
  if (prompt_ != 0) out += "-->";
}

// An LF is not echoed: after a CR it is the same line end, and a CR LF went back already.
void S300Wire::write_echo(std::string_view bytes, std::string& out) const {
  if (!echoes()) return;
  for (char c : bytes) {
    if (c == '\r')
      out += "\r\n";
    else if (c != '\n')
      out.push_back(c);
  }
}

void S300Wire::write_output(std::string_view text, std::string& out) const {
  for (char c : text) {
    if (c == '\n')
      out += "\r\n";
    else
      out.push_back(c);
  }
}

}  // namespace uprog::st
