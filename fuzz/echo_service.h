// The line service the transport targets put behind their boundary (fuzz_transport,
// fuzz_udp_datagram): it answers every line with its own text, and with an error for a line that
// starts with '!', over the wire the target builds from the input.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "transport/host_session.h"

template <class Wire>
class EchoService final : public uprog::transport::LineService {
 public:
  template <class... WireArguments>
  explicit EchoService(WireArguments&&... arguments)
      : wire_(std::forward<WireArguments>(arguments)...) {}
  std::vector<uprog::transport::Reply> handle_line(std::string_view line) override {
    if (!line.empty() && line[0] == '!') return {{std::string(line.substr(1)), 19}};
    return {{std::string(line), 0}};
  }
  void advance(std::uint32_t) override {}
  const uprog::dialect::WireForm& wire() const override { return wire_; }

 private:
  Wire wire_;
};
