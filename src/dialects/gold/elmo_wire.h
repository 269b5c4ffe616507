// The Gold drive's two wire forms (docs/protocol.md). The drive's own, the default: as the SimplIQ
// software manual (MAN-SIMSW, chapter 3) describes it, every character echoed while EO=1, a value
// answered `VALUE;`, a refused command answered with its EC code as one byte and `?;`, an empty
// expression answered `;`, nothing between lines and no prompt. uprog's readable form for people
// and tests: SemicolonWire's `?CODE TEXT;` and CR LF after each typed line, never an echo.
#pragma once
#include <functional>

#include "dialect/firmware.h"
#include "dialect/semicolon_wire.h"

namespace uprog::gold {

class ElmoWire final : public dialect::WireForm {
 public:
  // `framing`: how the command line splits expressions; `echo_on`: the drive's EO, read per byte.
  ElmoWire(dialect::WireStyle style, dialect::FramerOptions framing, std::function<bool()> echo_on);

  dialect::FramerOptions framing() const override { return framing_; }
  void write_answer(const dialect::Answer& answer, std::string& out) const override;
  void write_silent_line(std::string& out) const override { out.push_back(';'); }
  void write_line_end(std::string& out) const override;
  void write_output(std::string_view text, std::string& out) const override;
  void write_echo(std::string_view bytes, std::string& out) const override;
  bool echoes() const override { return drive_style() && echo_on_(); }
  dialect::Answer framing_error(const dialect::Answer& standard) const override;

 private:
  bool drive_style() const { return style_ == dialect::WireStyle::kDrive; }

  dialect::WireStyle style_;
  dialect::FramerOptions framing_;
  std::function<bool()> echo_on_;
  dialect::SemicolonWire readable_;
};

}  // namespace uprog::gold
