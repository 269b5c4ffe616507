// What a transport needs from the drive behind it: answer one host line, advance virtual time.
// The controller adapter implements it; tests use fakes. Called from one thread only.
#pragma once
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "transport/reply.h"

namespace uprog::transport {

// One host's lines, for a service that keeps state per host (a download in progress). The
// host's session owns it and drops it when the host goes away.
class LineChannel {
 public:
  virtual ~LineChannel() = default;
  virtual std::vector<Reply> handle_line(std::string_view line) = 0;
};

class LineService {
 public:
  virtual ~LineService() = default;
  // One command line, without its terminator; the answers in order (none for a silent line).
  virtual std::vector<Reply> handle_line(std::string_view line) = 0;
  // Lets `us` microseconds of virtual time pass.
  virtual void advance(std::uint32_t us) = 0;
  // A channel for a host that has just connected; nullptr (the default): every host's lines go
  // to handle_line() alike.
  virtual std::unique_ptr<LineChannel> open_channel() { return nullptr; }
};

}  // namespace uprog::transport
