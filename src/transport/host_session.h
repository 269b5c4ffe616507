// One host's conversation, free of I/O: bytes from the host in, bytes for the host out. Owns the
// host's line framer; every line gets at least one answer; CR/LF after a non-blank physical line
// is answered with CR LF, so a host knows when all answers to the line it typed have come.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "transport/line_framer.h"
#include "transport/line_service.h"

namespace uprog::transport {

class HostSession {
 public:
  explicit HostSession(LineService& service, FramerOptions options = {});

  // Appends to `out` everything to send back for `bytes`.
  void receive(std::string_view bytes, std::string& out);
  // The host went away: any partial line is dropped, and with the channel whatever the service
  // kept for this host (a download in progress); a host that comes back starts afresh.
  void disconnect();

 private:
  LineService& service_;
  std::unique_ptr<LineChannel> channel_;  // null when the service keeps nothing per host
  LineFramer framer_;
  std::vector<Frame> frames_;
};

}  // namespace uprog::transport
