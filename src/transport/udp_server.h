// The drive's UDP port, as Elmo drives speak over Ethernet: each datagram holds one command line
// (its end ends the line), and the reply datagram holds what the drive's serial wire sends for
// it. Bad datagrams do no harm: an empty one gets no reply, an oversized or binary one the
// wire's framing error. What the drive sends on its own goes to every recent peer.
#pragma once
#include <array>
#include <boost/asio/ip/udp.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "transport/asio.h"
#include "transport/host_session.h"
#include "transport/line_service.h"

namespace uprog::transport {

inline constexpr std::size_t kMaxDatagramBytes = 65507;   // the largest UDP payload over IPv4
inline constexpr std::size_t kMaxUdpPeers = 16;           // peers with a session of their own
inline constexpr std::size_t kMaxUdpSendsInFlight = 256;  // beyond: a reply is dropped

// One peer's datagrams, free of I/O (the UDP server's and the fuzz target's).
class DatagramHost {
 public:
  explicit DatagramHost(LineService& service) : service_(service), session_(service) {}

  // The reply to one datagram; empty when there is nothing to send.
  std::string answer(std::string_view datagram);
  // A text the drive sent on its own, as a datagram for this peer.
  std::string output(std::string_view text) const;

 private:
  LineService& service_;
  HostSession session_;
};

class UdpServer {
 public:
  // Binds at once (throws boost::system::system_error if it cannot).
  UdpServer(boost::asio::io_context& io, LineService& service,
            const boost::asio::ip::udp::endpoint& endpoint);
  ~UdpServer();
  UdpServer(const UdpServer&) = delete;
  UdpServer& operator=(const UdpServer&) = delete;

  boost::asio::ip::udp::endpoint local_endpoint() const { return socket_.local_endpoint(); }
  void stop();

 private:
  struct Peer {
    std::unique_ptr<DatagramHost> host;
    std::uint64_t last_used = 0;
  };

  void receive();
  DatagramHost& peer(const boost::asio::ip::udp::endpoint& from);
  void send(const boost::asio::ip::udp::endpoint& to, std::string bytes);

  boost::asio::ip::udp::socket socket_;
  LineService& service_;
  std::uint64_t output_listener_ = 0;
  std::array<char, 65536> buffer_{};
  boost::asio::ip::udp::endpoint sender_;
  std::map<boost::asio::ip::udp::endpoint, Peer> peers_;
  std::uint64_t datagrams_ = 0;
  std::size_t sends_in_flight_ = 0;
};

// "HOST:PORT", "[V6]:PORT" or "PORT" (loopback), as parse_endpoint() reads a TCP one.
bool parse_udp_endpoint(std::string_view text, boost::asio::ip::udp::endpoint& endpoint,
                        std::string& error);

}  // namespace uprog::transport
