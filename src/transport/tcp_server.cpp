// The TCP server and its endpoint parser (tcp_server.h).
#include "transport/tcp_server.h"

#include <charconv>

namespace uprog::transport {

namespace asio = boost::asio;
using asio::ip::tcp;

TcpServer::TcpServer(asio::io_context& io, LineService& service, const tcp::endpoint& endpoint)
    : acceptor_(io), service_(service) {
  // What the drive sends on its own reaches every connected host.
  output_listener_ = service_.add_output_listener([this](std::string_view text) {
    for (auto& [id, weak] : sessions_) {
      if (auto session = weak.lock()) session->deliver_output(text);
    }
  });
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
  accept();
}

void TcpServer::accept() {
  acceptor_.async_accept([this](const boost::system::error_code& ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;
    if (!ec) {
      boost::system::error_code ignored;
      socket.set_option(tcp::no_delay(true), ignored);
      const std::uint64_t id = next_id_++;
      auto session = std::make_shared<Session>(std::move(socket), service_,
                                               [this, id] { sessions_.erase(id); });
      sessions_.emplace(id, session);
      session->start();
    }
    accept();  // a failed accept (too many files) does not stop the server
  });
}

TcpServer::~TcpServer() { service_.remove_output_listener(output_listener_); }

void TcpServer::stop() {
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  auto sessions = sessions_;
  for (auto& [id, weak] : sessions) {
    if (auto session = weak.lock()) session->close();
  }
  sessions_.clear();
}

bool parse_endpoint(std::string_view text, tcp::endpoint& endpoint, std::string& error) {
  std::string_view host = "127.0.0.1";
  std::string_view port = text;
  if (const auto colon = text.rfind(':'); colon != std::string_view::npos) {
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
      host = host.substr(1, host.size() - 2);
    }
  }
  unsigned number = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), number);
  if (ec != std::errc{} || end != port.data() + port.size() || number > 65535) {
    error = "bad port in '" + std::string(text) + "' (expected HOST:PORT)";
    return false;
  }
  boost::system::error_code address_error;
  const auto address = asio::ip::make_address(std::string(host), address_error);
  if (address_error) {
    error = "bad address '" + std::string(host) + "' (expected a numeric IPv4 or IPv6 address)";
    return false;
  }
  endpoint = tcp::endpoint(address, static_cast<unsigned short>(number));
  return true;
}

}  // namespace uprog::transport
