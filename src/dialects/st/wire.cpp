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

// The drive's wire answers CR alone with the prompt again; the readable form drops empty lines.
dialect::FramerOptions S300Wire::framing() const {
  dialect::FramerOptions o = framing_options();
  o.break_empty_lines = drive_style();
  return o;
}

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

// A line's end comes back as CR LF, whether it was CR, LF or CR LF: the LF after a CR is the
// same line end, and its CR LF went back already. PROMPT is read at each byte; the bytes are
// followed with PROMPT=0 too, so a CR LF split by `PROMPT 1` is still one line end.
void S300Wire::write_echo(std::string_view bytes, std::string& out) const {
  if (!drive_style()) return;
  for (char c : bytes) {
    const bool lf_of_cr_lf = c == '\n' && after_cr_;
    after_cr_ = c == '\r';
    if (prompt_ == 0) continue;
    if (c == '\r' || (c == '\n' && !lf_of_cr_lf))
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
