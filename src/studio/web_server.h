// The studio's HTTP and WebSocket server (Boost.Beast, one thread, the caller's io_context): the
// page's files from one folder, and WebSockets on the paths the studio routes. Bounded: a request
// head and body, a WebSocket message and what a peer leaves unread each have a limit; past it the
// peer is answered (413, close 1009) or dropped, and the server goes on.
#pragma once
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "transport/asio.h"

namespace uprog::studio {

struct WebLimits {
  size_t max_message_bytes = size_t{1} << 20;  // one WebSocket message in
  size_t max_unread_bytes = size_t{16} << 20;  // queued for a peer that does not read
  size_t max_request_bytes = 16 * 1024;        // an HTTP request's head and body
};

// One accepted WebSocket, as a route sees it.
class WebSocketPeer {
 public:
  virtual ~WebSocketPeer() = default;
  virtual void send_text(std::string text) = 0;
  virtual void send_binary(std::string bytes) = 0;
  // What is queued for the peer and not yet written to its socket.
  virtual size_t queued_bytes() const = 0;
  // Closes with a WebSocket close code and reason; nothing more is sent or received.
  virtual void close(uint16_t code, std::string reason) = 0;
};

// What a route does with its connection's messages; on_close comes once, when it is gone.
struct WebSocketHandler {
  std::function<void(const std::string& message)> on_message;
  std::function<void()> on_close;
};

class WebServer {
 public:
  using Route = std::function<WebSocketHandler(std::shared_ptr<WebSocketPeer> peer)>;

  // Binds and listens at once (throws boost::system::system_error if it cannot). `page_folder`
  // holds index.html and what it loads.
  WebServer(boost::asio::io_context& io, const boost::asio::ip::tcp::endpoint& endpoint,
            std::string page_folder, WebLimits limits = {});
  ~WebServer();
  // A WebSocket path ("/ws/drive"); an upgrade to any other path gets 404.
  void route(const std::string& path, Route route);
  boost::asio::ip::tcp::endpoint local_endpoint() const;
  void stop();

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace uprog::studio
