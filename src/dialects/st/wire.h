// The S300's ASCII wire (shared/spec/s300-drive.md, "The ASCII interface"): lines end with CR
// (LF, CR LF too); with PROMPT=1 the input is echoed with CR LF, each answer line ends with
// CR LF, an error is BEL `ERR code text`, and the prompt `-->` follows; PROMPT=0: no echo, no
// prompt. Unsolicited text comes between answers. The readable form (`uprog sim --wire
// readable`, for `uprog term` and other uprog hosts) is docs/protocol.md's: `TEXT;`, `?CODE
// TEXT;`, `;` for a line without answers, CR LF after each line, no echo and no prompt.
#pragma once
#include <string>
#include <string_view>

#include "dialect/semicolon_wire.h"
#include "dialect/wire_form.h"

namespace uprog::st {

class S300Wire final : public dialect::WireForm {
 public:
  // `prompt` is the drive's PROMPT parameter, read at each line.
  S300Wire(const int32_t& prompt, dialect::WireStyle style);
  dialect::FramerOptions framing() const override;
  void write_answer(const dialect::Answer& answer, std::string& out) const override;
  void write_silent_line(std::string& out) const override;
  void write_line_end(std::string& out) const override;
  // PROMPT=1: every byte comes back as it arrives, the CR or LF that ends a line as CR LF.
  void write_echo(std::string_view bytes, std::string& out) const override;
  // The drive's wire takes the bytes one by one whatever PROMPT is (write_echo decides).
  bool echoes() const override { return drive_style(); }
  void write_output(std::string_view text, std::string& out) const override;

 private:
  bool drive_style() const { return style_ == dialect::WireStyle::kDrive; }

  const int32_t& prompt_;
  dialect::WireStyle style_;
  dialect::SemicolonWire readable_;
  mutable bool after_cr_ = false;  // the last byte was a CR (an LF right after it adds nothing)
};

// One answer as the wire writes it, without the line end: "\aERR 1 unknown" or the text.
std::string answer_text(const dialect::Answer& answer);

}  // namespace uprog::st
