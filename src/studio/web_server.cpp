// The studio's Beast server (web_server.h): an HTTP session per connection that serves the page's
// files and hands an upgrade to a WebSocket session on its route.
#include "studio/web_server.h"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <utility>  // before Beast: Boost 1.74's asio misses it under g++ 12 (transport/asio.h)

#include "studio/page_files.h"

namespace uprog::studio {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

struct WebServer::State {
  explicit State(asio::io_context& io_) : io(io_), acceptor(io_) {}
  asio::io_context& io;
  tcp::acceptor acceptor;
  std::string page_folder;
  WebLimits limits;
  std::map<std::string, Route> routes;
  bool stopped = false;
};

namespace {

constexpr auto kIdleHttp = std::chrono::seconds(60);

class WebSocketSession final : public WebSocketPeer,
                               public std::enable_shared_from_this<WebSocketSession> {
 public:
  WebSocketSession(tcp::socket socket, std::shared_ptr<WebServer::State> state)
      : ws_(std::move(socket)), state_(std::move(state)) {}

  void run(http::request<http::string_body> request, WebServer::Route route) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(state_->limits.max_message_bytes);
    ws_.async_accept(request, [self = shared_from_this(),
                               route = std::move(route)](beast::error_code ec) mutable {
      if (ec) return;
      self->handler_ = route(self);
      self->read();
    });
  }

  void send_text(std::string text) override { queue(std::move(text), false); }
  void send_binary(std::string bytes) override { queue(std::move(bytes), true); }
  size_t queued_bytes() const override { return queued_bytes_; }

  void close(uint16_t code, std::string reason) override {
    if (closing_) return;
    closing_ = true;
    queue_.clear();
    queued_bytes_ = 0;
    if (writing_) {
      // A close frame may not overlap a write: drop the connection instead.
      return drop_later();
    }
    websocket::close_reason why;
    why.code = code;
    why.reason = reason;
    ws_.async_close(why, [self = shared_from_this()](beast::error_code) { self->gone(); });
  }

 private:
  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, size_t) {
      if (ec) return self->gone();  // closed, dropped, or too big (Beast answers 1009 then)
      std::string message = beast::buffers_to_string(self->buffer_.data());
      self->buffer_.consume(self->buffer_.size());
      if (self->handler_.on_message && !self->closing_) self->handler_.on_message(message);
      if (!self->closed_) self->read();
    });
  }

  void queue(std::string bytes, bool binary) {
    if (closing_ || closed_) return;
    queued_bytes_ += bytes.size();
    if (queued_bytes_ > state_->limits.max_unread_bytes) {
      // A peer that does not read what it asked for is dropped, not buffered without end.
      closing_ = true;
      return drop_later();
    }
    queue_.push_back({std::move(bytes), binary});
    if (!writing_) write();
  }

  void write() {
    writing_ = true;
    ws_.binary(queue_.front().binary);
    ws_.async_write(asio::buffer(queue_.front().bytes),
                    [self = shared_from_this()](beast::error_code ec, size_t) {
                      self->writing_ = false;
                      if (ec) return self->gone();
                      if (self->queue_.empty()) return;  // cleared by a close
                      self->queued_bytes_ -= self->queue_.front().bytes.size();
                      self->queue_.pop_front();
                      if (!self->queue_.empty() && !self->closed_) self->write();
                    });
  }

  // Dropped from a handler of its own: the caller (a route's send, deep in a drive's or a
  // server's message handling) must not see its on_close run under its feet.
  void drop_later() {
    asio::post(ws_.get_executor(), [self = shared_from_this()] { self->drop(); });
  }

  void drop() {
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
    beast::get_lowest_layer(ws_).socket().close(ignored);
    gone();
  }

  // The handler's on_close, once.
  void gone() {
    if (closed_) return;
    closed_ = true;
    queue_.clear();
    queued_bytes_ = 0;
    if (handler_.on_close) handler_.on_close();
    handler_ = {};
  }

  struct Outgoing {
    std::string bytes;
    bool binary;
  };
  websocket::stream<beast::tcp_stream> ws_;
  std::shared_ptr<WebServer::State> state_;
  beast::flat_buffer buffer_;
  WebSocketHandler handler_;
  std::deque<Outgoing> queue_;
  size_t queued_bytes_ = 0;
  bool writing_ = false;
  bool closing_ = false;
  bool closed_ = false;
};

class HttpSession final : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, std::shared_ptr<WebServer::State> state)
      : stream_(std::move(socket)), state_(std::move(state)) {}

  void read() {
    parser_.emplace();
    parser_->header_limit(static_cast<uint32_t>(state_->limits.max_request_bytes));
    parser_->body_limit(state_->limits.max_request_bytes);
    stream_.expires_after(kIdleHttp);
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, size_t) { self->on_request(ec); });
  }

 private:
  void on_request(beast::error_code ec) {
    if (ec == http::error::end_of_stream || ec == beast::error::timeout ||
        ec == asio::error::operation_aborted)
      return close();
    if (ec == http::error::body_limit || ec == http::error::header_limit)
      return answer_status(http::status::payload_too_large, "request too large\n", false);
    if (ec) return answer_status(http::status::bad_request, "bad request\n", false);
    http::request<http::string_body> request = parser_->release();
    if (websocket::is_upgrade(request)) return upgrade(std::move(request));
    if (request.method() != http::verb::get && request.method() != http::verb::head)
      return answer_status(http::status::method_not_allowed, "GET only\n", request.keep_alive());
    serve_file(request);
  }

  void upgrade(http::request<http::string_body> request) {
    const std::string target(request.target().substr(0, request.target().find('?')));
    const auto route = state_->routes.find(target);
    if (route == state_->routes.end())
      return answer_status(http::status::not_found, "no such WebSocket\n", false);
    stream_.expires_never();
    std::make_shared<WebSocketSession>(stream_.release_socket(), state_)
        ->run(std::move(request), route->second);
  }

  void serve_file(const http::request<http::string_body>& request) {
    const auto target = request.target();
    const auto path =
        page_file_path(state_->page_folder, std::string_view(target.data(), target.size()));
    http::file_body::value_type body;
    beast::error_code ec;
    if (path) body.open(path->c_str(), beast::file_mode::scan, ec);
    if (!path || ec)
      return answer_status(http::status::not_found, "not found\n", request.keep_alive());
    const uint64_t size = body.size();
    auto response = std::make_shared<http::response<http::file_body>>(
        std::piecewise_construct, std::make_tuple(std::move(body)),
        std::make_tuple(http::status::ok, request.version()));
    response->set(http::field::content_type, std::string(content_type(*path)));
    response->set(http::field::cache_control, "no-cache");
    response->content_length(size);
    response->keep_alive(request.keep_alive());
    if (request.method() == http::verb::head) response->body().close();
    send(response, request.keep_alive());
  }

  void answer_status(http::status status, const std::string& text, bool keep_alive) {
    auto response = std::make_shared<http::response<http::string_body>>(status, 11);
    response->set(http::field::content_type, "text/plain; charset=utf-8");
    response->body() = text;
    response->keep_alive(keep_alive);
    response->prepare_payload();
    send(response, keep_alive);
  }

  template <class Response>
  void send(std::shared_ptr<Response> response, bool keep_alive) {
    stream_.expires_after(kIdleHttp);
    http::async_write(
        stream_, *response,
        [self = shared_from_this(), response, keep_alive](beast::error_code ec, size_t) {
          // A client gone mid-download ends here; the server goes on.
          if (ec || !keep_alive) return self->close();
          self->read();
        });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream_.close();
  }

  beast::tcp_stream stream_;
  std::shared_ptr<WebServer::State> state_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

void accept(const std::shared_ptr<WebServer::State>& state) {
  state->acceptor.async_accept([state](beast::error_code ec, tcp::socket socket) {
    if (state->stopped || ec == asio::error::operation_aborted) return;
    if (!ec) {
      beast::error_code ignored;
      socket.set_option(tcp::no_delay(true), ignored);  // answers go out as they are made
      std::make_shared<HttpSession>(std::move(socket), state)->read();
    }
    accept(state);
  });
}

}  // namespace

WebServer::WebServer(asio::io_context& io, const tcp::endpoint& endpoint, std::string page_folder,
                     WebLimits limits)
    : state_(std::make_shared<State>(io)) {
  state_->page_folder = std::move(page_folder);
  state_->limits = limits;
  state_->acceptor.open(endpoint.protocol());
  state_->acceptor.set_option(tcp::acceptor::reuse_address(true));
  state_->acceptor.bind(endpoint);
  state_->acceptor.listen();
  accept(state_);
}

WebServer::~WebServer() { stop(); }

void WebServer::route(const std::string& path, Route route) {
  state_->routes[path] = std::move(route);
}

tcp::endpoint WebServer::local_endpoint() const { return state_->acceptor.local_endpoint(); }

void WebServer::stop() {
  state_->stopped = true;
  beast::error_code ignored;
  state_->acceptor.close(ignored);
}

}  // namespace uprog::studio
