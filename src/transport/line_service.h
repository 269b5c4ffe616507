// What a transport needs from the drive behind it: answer one host line, advance virtual time.
// The controller adapter implements it; tests use fakes. Called from one thread only.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include "transport/reply.h"

namespace uprog::transport {

class LineService {
 public:
  virtual ~LineService() = default;
  // One command line, without its terminator; the answers in order (none for a silent line).
  virtual std::vector<Reply> handle_line(std::string_view line) = 0;
  // Lets `us` microseconds of virtual time pass.
  virtual void advance(std::uint32_t us) = 0;
};

}  // namespace uprog::transport
