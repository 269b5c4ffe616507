// The AG300's wire form: the shared semicolon form (docs/protocol.md), and a line the framer
// refused (too long, a bad byte) is a communication error, event 23, as well as its answer.
#pragma once
#include <cstdint>
#include <functional>
#include <utility>

#include "dialect/semicolon_wire.h"

namespace uprog::pup {

class PupWire final : public dialect::WireForm {
 public:
  PupWire(dialect::FramerOptions framing, std::function<void(int32_t)> on_framing_error)
      : wire_(framing), on_framing_error_(std::move(on_framing_error)) {}
  dialect::FramerOptions framing() const override { return wire_.framing(); }
  void write_answer(const dialect::Answer& answer, std::string& out) const override {
    wire_.write_answer(answer, out);
  }
  void write_silent_line(std::string& out) const override { wire_.write_silent_line(out); }
  void write_line_end(std::string& out) const override { wire_.write_line_end(out); }
  void write_output(std::string_view text, std::string& out) const override {
    wire_.write_output(text, out);
  }
  dialect::Answer framing_error(const dialect::Answer& standard) const override {
    on_framing_error_(standard.error);
    return standard;
  }

 private:
  dialect::SemicolonWire wire_;
  std::function<void(int32_t)> on_framing_error_;  // with the code, 900 or 901
};

}  // namespace uprog::pup
