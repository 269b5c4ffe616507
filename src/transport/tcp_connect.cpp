// Resolving and connecting to a drive's address.
#include "transport/tcp_connect.h"

namespace uprog::transport {

bool connect_tcp(asio::io_context& io, const std::string& address, asio::ip::tcp::socket& socket,
                 std::string& error) {
  const auto colon = address.rfind(':');
  if (colon == std::string::npos) {
    error = "expected HOST:PORT, got '" + address + "'";
    return false;
  }
  std::string host = address.substr(0, colon);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  boost::system::error_code ec;
  asio::ip::tcp::resolver resolver(io);
  const auto endpoints = resolver.resolve(host, address.substr(colon + 1), ec);
  if (!ec) asio::connect(socket, endpoints, ec);
  if (ec) {
    error = "cannot connect to " + address + ": " + ec.message();
    return false;
  }
  return true;
}

}  // namespace uprog::transport
