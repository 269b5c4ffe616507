// A LineService for the transport's tests: echoes a line back, "err N" answers error N, "quiet"
// answers nothing, "two" answers twice; counts lines and the virtual time it was given. Its wire
// is the semicolon wire with Gold's framing (`;`, `**`, 511), with PDL's `%L n` when asked.
#pragma once
#include <charconv>
#include <cstdint>

#include "dialect/semicolon_wire.h"
#include "transport/line_service.h"

namespace uprog::transport::testing {

// The semicolon wire with Gold's framing (`;`, `**`, 511), as the fakes speak it.
inline const dialect::WireForm& semicolon_wire() {
  static const dialect::SemicolonWire wire = [] {
    dialect::FramerOptions o;
    o.max_line_length = 511;
    o.semicolon_ends_line = true;
    o.comment_marker = "**";
    return dialect::SemicolonWire(o);
  }();
  return wire;
}

// The same with PDL's count of dropped texts (`%L n`).
inline const dialect::WireForm& lost_counting_wire() {
  static const dialect::SemicolonWire wire(semicolon_wire().framing(), "%L ");
  return wire;
}

class FakeService final : public LineService {
 public:
  std::vector<Reply> handle_line(std::string_view line) override {
    ++lines;
    if (line == "quiet") return {};
    if (line == "two") return {{"1", 0}, {"2", 0}};
    if (line == "now") return {{std::to_string(advanced_us), 0}};
    if (line.starts_with("err ")) {
      std::int32_t code = 0;
      std::from_chars(line.data() + 4, line.data() + line.size(), code);
      return {{"Failed", code}};
    }
    return {{std::string(line), 0}};
  }
  void advance(std::uint32_t us) override {
    advanced_us += us;
    ++advances;
  }
  const dialect::WireForm& wire() const override {
    return counts_lost ? lost_counting_wire() : semicolon_wire();
  }
  // Sends `text` to every host as the drive's own output.
  void emit(std::string_view text) { publish_output(text); }

  std::uint64_t lines = 0;
  std::uint64_t advanced_us = 0;
  std::uint64_t advances = 0;
  bool counts_lost = false;
};

}  // namespace uprog::transport::testing
