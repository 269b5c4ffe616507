// The Gold drive's wire forms (elmo_wire.h).
#include "dialects/gold/elmo_wire.h"

#include "dialects/gold/interpreter_errors.h"

namespace uprog::gold {

ElmoWire::ElmoWire(dialect::WireStyle style, dialect::FramerOptions framing,
                   std::function<bool()> echo_on)
    : style_(style), framing_(framing), echo_on_(std::move(echo_on)), readable_(framing) {
  // A real drive answers every terminator, an empty expression too (host drivers send `;` alone
  // to see that the drive is there).
  framing_.answer_empty_expressions = drive_style();
}

void ElmoWire::write_answer(const dialect::Answer& answer, std::string& out) const {
  if (!drive_style()) return readable_.write_answer(answer, out);
  if (answer.error == 0) return dialect::append_semicolon_answer(answer, out);
  // "{value}{error code}<terminator>": the code as a binary byte, then `?;` (MAN-SIMSW 3.1).
  const int32_t code = answer.error > 0 && answer.error < 256 ? answer.error : kErrorSyntax;
  out.push_back(static_cast<char>(code));
  out += "?;";
}

void ElmoWire::write_line_end(std::string& out) const {
  if (!drive_style()) readable_.write_line_end(out);
}

void ElmoWire::write_output(std::string_view text, std::string& out) const {
  readable_.write_output(text, out);
}

void ElmoWire::write_echo(std::string_view bytes, std::string& out) const {
  if (echoes()) out += bytes;
}

dialect::Answer ElmoWire::framing_error(const dialect::Answer& standard) const {
  // The drive's own codes fit a byte; the transport's 900 and 901 do not. A drive refuses such a
  // line as a syntax error, which is what EC names too.
  if (!drive_style()) return standard;
  return {standard.text, kErrorSyntax};
}

}  // namespace uprog::gold
