// The drive's serial port, simulated: a pseudo-terminal in raw mode whose slave path (/dev/pts/N)
// picocom, screen or socat open as they would a real RS-232 port. Same framing and answers as TCP.
#pragma once
#include <memory>
#include <string>

#include "transport/asio.h"
#include "transport/line_service.h"
#include "transport/stream_session.h"

namespace uprog::transport {

class PtyServer {
 public:
  using Session = StreamSession<boost::asio::posix::stream_descriptor>;

  // Opens the pty (throws boost::system::system_error if it cannot).
  PtyServer(boost::asio::io_context& io, LineService& service);
  ~PtyServer();
  PtyServer(const PtyServer&) = delete;
  PtyServer& operator=(const PtyServer&) = delete;

  const std::string& slave_path() const { return slave_path_; }
  void stop();

 private:
  LineService& service_;
  std::uint64_t output_listener_ = 0;
  std::shared_ptr<Session> session_;
  std::string slave_path_;
  int slave_fd_ = -1;  // held open so the master never reads EIO between two terminal programs
};

}  // namespace uprog::transport
