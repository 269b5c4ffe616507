// The UDP server and its per-datagram framing (udp_server.h).
#include "transport/udp_server.h"

#include "transport/tcp_server.h"

namespace uprog::transport {

namespace asio = boost::asio;
using asio::ip::udp;

std::string DatagramHost::answer(std::string_view datagram) {
  std::string out;
  if (datagram.empty()) return out;  // no command in it: nothing to answer
  session_.receive(datagram, out);
  // The datagram's end ends its line, as a terminator would.
  const char last = datagram.back();
  const bool ended = last == '\r' || last == '\n' ||
                     (last == ';' && service_.wire().framing().semicolon_ends_line);
  if (!ended) session_.end_line(out);
  if (out.size() > kMaxDatagramBytes) out.resize(kMaxDatagramBytes);
  return out;
}

std::string DatagramHost::output(std::string_view text) const {
  std::string out;
  session_.deliver_output(text, out);
  if (out.size() > kMaxDatagramBytes) out.resize(kMaxDatagramBytes);
  return out;
}

UdpServer::UdpServer(asio::io_context& io, LineService& service, const udp::endpoint& endpoint)
    : socket_(io), service_(service) {
  output_listener_ = service_.add_output_listener([this](std::string_view text) {
    for (auto& [to, peer] : peers_) send(to, peer.host->output(text));
  });
  socket_.open(endpoint.protocol());
  socket_.bind(endpoint);
  receive();
}

UdpServer::~UdpServer() { service_.remove_output_listener(output_listener_); }

void UdpServer::stop() {
  boost::system::error_code ignored;
  socket_.close(ignored);
  peers_.clear();
}

void UdpServer::receive() {
  socket_.async_receive_from(
      asio::buffer(buffer_), sender_, [this](const boost::system::error_code& ec, std::size_t n) {
        if (ec == asio::error::operation_aborted || !socket_.is_open()) return;
        // An error on one datagram (a peer's ICMP "unreachable", say) stops nothing.
        if (!ec) send(sender_, peer(sender_).answer(std::string_view(buffer_.data(), n)));
        receive();
      });
}

DatagramHost& UdpServer::peer(const udp::endpoint& from) {
  ++datagrams_;
  auto it = peers_.find(from);
  if (it == peers_.end()) {
    if (peers_.size() >= kMaxUdpPeers) {
      // The peer heard from longest ago gives its place (and its partial state) up.
      auto oldest = peers_.begin();
      for (auto p = peers_.begin(); p != peers_.end(); ++p)
        if (p->second.last_used < oldest->second.last_used) oldest = p;
      peers_.erase(oldest);
    }
    it = peers_.emplace(from, Peer{std::make_unique<DatagramHost>(service_), 0}).first;
  }
  it->second.last_used = datagrams_;
  return *it->second.host;
}

void UdpServer::send(const udp::endpoint& to, std::string bytes) {
  if (bytes.empty() || sends_in_flight_ >= kMaxUdpSendsInFlight) return;
  ++sends_in_flight_;
  auto buffer = std::make_shared<std::string>(std::move(bytes));
  socket_.async_send_to(
      asio::buffer(*buffer), to,
      [this, buffer](const boost::system::error_code&, std::size_t) { --sends_in_flight_; });
}

bool parse_udp_endpoint(std::string_view text, udp::endpoint& endpoint, std::string& error) {
  asio::ip::tcp::endpoint tcp;
  if (!parse_endpoint(text, tcp, error)) return false;
  endpoint = udp::endpoint(tcp.address(), tcp.port());
  return true;
}

}  // namespace uprog::transport
