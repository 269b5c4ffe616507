// The drive's TCP port: accepts any number of hosts, each with its own line buffer, all served
// on the io_context's one thread by one LineService, so answers keep each host's order.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "transport/asio.h"
#include "transport/line_service.h"
#include "transport/stream_session.h"

namespace uprog::transport {

class TcpServer {
 public:
  using Session = StreamSession<boost::asio::ip::tcp::socket>;

  // Binds and listens at once (throws boost::system::system_error if it cannot).
  TcpServer(boost::asio::io_context& io, LineService& service,
            const boost::asio::ip::tcp::endpoint& endpoint);

  ~TcpServer();
  TcpServer(const TcpServer&) = delete;
  TcpServer& operator=(const TcpServer&) = delete;

  boost::asio::ip::tcp::endpoint local_endpoint() const { return acceptor_.local_endpoint(); }
  std::size_t session_count() const { return sessions_.size(); }
  // Stops accepting and closes every connection.
  void stop();

 private:
  void accept();

  boost::asio::ip::tcp::acceptor acceptor_;
  LineService& service_;
  std::uint64_t output_listener_ = 0;
  std::map<std::uint64_t, std::weak_ptr<Session>> sessions_;
  std::uint64_t next_id_ = 0;
};

// "HOST:PORT", "[V6]:PORT" or "PORT" (loopback) → an endpoint; false with `error` set if bad.
bool parse_endpoint(std::string_view text, boost::asio::ip::tcp::endpoint& endpoint,
                    std::string& error);

}  // namespace uprog::transport
