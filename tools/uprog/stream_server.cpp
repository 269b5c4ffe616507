// One client over stdin/stdout or TCP for the protocol servers (stream_server.h).
#include "stream_server.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>

#include "transport/asio.h"
#include "transport/tcp_server.h"

namespace uprog::cli {

bool write_all(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

int serve_one_tcp_client(const char* tool, const std::string& where,
                         const std::function<int(int in, int out)>& serve) {
  namespace asio = boost::asio;
  asio::ip::tcp::endpoint endpoint;
  std::string error;
  if (!transport::parse_endpoint(where, endpoint, error)) {
    fmt::print(stderr, "{}: --listen {}: {}\n", tool, where, error);
    return 2;
  }
  asio::io_context io;
  boost::system::error_code ec;
  asio::ip::tcp::acceptor acceptor(io);
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(asio::ip::tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (!ec) acceptor.listen(1, ec);
  if (ec) {
    fmt::print(stderr, "{}: cannot listen on {}: {}\n", tool, where, ec.message());
    return 1;
  }
  const auto local = acceptor.local_endpoint();
  fmt::print(stderr, "{}: listening on tcp {}:{}\n", tool, local.address().to_string(),
             local.port());
  asio::ip::tcp::socket socket(io);
  acceptor.accept(socket, ec);
  if (ec) {
    fmt::print(stderr, "{}: accept failed: {}\n", tool, ec.message());
    return 1;
  }
  return serve(socket.native_handle(), socket.native_handle());
}

}  // namespace uprog::cli
