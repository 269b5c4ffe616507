// A LineService for the transport's tests: echoes a line back, "err N" answers error N, "quiet"
// answers nothing, "two" answers twice; counts lines and the virtual time it was given.
#pragma once
#include <charconv>
#include <cstdint>

#include "transport/line_service.h"

namespace uprog::transport::testing {

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

  std::uint64_t lines = 0;
  std::uint64_t advanced_us = 0;
  std::uint64_t advances = 0;
};

}  // namespace uprog::transport::testing
