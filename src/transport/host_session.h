// One host's conversation, free of I/O: bytes from the host in, bytes for the host out. Owns the
// host's line framer (the drive's framing); every line gets at least one answer; after a
// non-blank physical line comes the wire's line end, so a host knows when all answers to the
// line it typed have come.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "dialect/line_framer.h"
#include "transport/line_service.h"

namespace uprog::transport {

class HostSession {
 public:
  explicit HostSession(LineService& service);

  // Appends to `out` everything to send back for `bytes`.
  void receive(std::string_view bytes, std::string& out);
  // Appends text the drive sent on its own, in the wire's form.
  void deliver_output(std::string_view text, std::string& out) const;
  // Appends the wire's notice that `count` such texts were dropped (it may have none).
  void deliver_lost_output(uint64_t count, std::string& out) const;
  // The host went away: any partial line is dropped, and with the channel whatever the service
  // kept for this host (a download in progress); a host that comes back starts afresh.
  void disconnect();
  // Ends the line being received as CR would, without echoing anything (a datagram's end).
  void end_line(std::string& out) { take("\r", out); }

 private:
  void take(std::string_view bytes, std::string& out);

  LineService& service_;
  std::unique_ptr<LineChannel> channel_;  // null when the service keeps nothing per host
  dialect::LineFramer framer_;
  std::vector<dialect::Frame> frames_;
};

}  // namespace uprog::transport
