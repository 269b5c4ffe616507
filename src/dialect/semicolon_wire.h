// The wire form Gold, PDL and Akribis drives share (docs/protocol.md): a value is `TEXT;`, an
// error `?CODE TEXT;`, a line without answers `;`, CR LF after the answers to a typed line; `;`
// also ends a line where the dialect's framing says so. Also the host's side: reading it back.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "dialect/wire_form.h"

namespace uprog::dialect {

class SemicolonWire final : public WireForm {
 public:
  // `lost_prefix`: what starts the line that counts dropped texts (`%L ` for PDL); empty, none.
  explicit SemicolonWire(FramerOptions framing, std::string lost_prefix = {})
      : framing_(framing), lost_prefix_(std::move(lost_prefix)) {}
  FramerOptions framing() const override { return framing_; }
  void write_answer(const Answer& answer, std::string& out) const override;
  void write_silent_line(std::string& out) const override { out.push_back(';'); }
  void write_line_end(std::string& out) const override { out += "\r\n"; }
  void write_output(std::string_view text, std::string& out) const override;
  void write_lost_output(uint64_t count, std::string& out) const override;

 private:
  FramerOptions framing_;
  std::string lost_prefix_;
};

// Appends the wire form of `answer`. `;`, CR, LF and control bytes inside the text become a space
// so that the answer stays one frame; an error's text never starts with a digit.
void append_semicolon_answer(const Answer& answer, std::string& out);

// Reads one answer's wire form (without its `;`) back: `?21 text` → {text, 21}. A `?` without a
// code gives error -1.
Answer parse_semicolon_answer(std::string_view answer);

}  // namespace uprog::dialect
