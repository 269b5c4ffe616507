// The sim's debugger port (sim_debugger.h).
#include "sim_debugger.h"

#include <fmt/core.h>

namespace uprog::cli {

namespace asio = boost::asio;
using asio::ip::tcp;

SimDebugger::SimDebugger(asio::io_context& io, controller::Controller& drive,
                         transport::ControllerService& service, const tcp::endpoint& endpoint)
    : acceptor_(io), drive_(drive), service_(service) {
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
  service_.set_time_keeper([this](std::uint64_t ns) { return server_ && server_->keep_time(ns); },
                           [this] {
                             if (server_) server_->after_host_line();
                           });
  output_listener_ = service_.add_output_listener([this](std::string_view text) {
    if (server_) server_->program_output(std::string(text));
  });
  accept();
}

SimDebugger::~SimDebugger() {
  service_.set_time_keeper({}, {});
  service_.remove_output_listener(output_listener_);
  server_.reset();  // detaches: the program goes on as it was
}

void SimDebugger::stop() {
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  if (socket_) socket_->close(ignored);
  server_.reset();
}

// One client at a time: the next connection is taken once this one has ended.
void SimDebugger::accept() {
  acceptor_.async_accept([this](const boost::system::error_code& ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;
    if (ec) return accept();
    boost::system::error_code ignored;
    socket.set_option(tcp::no_delay(true), ignored);
    socket_ = std::make_unique<tcp::socket>(std::move(socket));
    reader_ = jsonrpc::MessageReader{};
    debug::DapOptions options;
    options.choose_dialect = [](const std::string&, const std::string&, std::string& error) {
      error = "this drive's debugger attaches to the program it runs";
      return static_cast<const dialect::Dialect*>(nullptr);
    };
    options.attach_target = &drive_;
    server_ = std::make_unique<debug::DapServer>(std::move(options),
                                                 [this](const std::string& m) { send(m); });
    read();
  });
}

void SimDebugger::read() {
  socket_->async_read_some(asio::buffer(buffer_),
                           [this](const boost::system::error_code& ec, std::size_t n) {
                             if (ec == asio::error::operation_aborted || !server_) return;
                             if (ec) return end_session();
                             reader_.feed(std::string_view(buffer_, n));
                             while (auto message = reader_.next()) {
                               server_->handle(*message);
                               if (server_->done()) return end_session();
                             }
                             for (const std::string& problem : reader_.take_problems())
                               fmt::print(stderr, "uprog sim: debugger: {}\n", problem);
                             read();
                           });
}

void SimDebugger::send(const std::string& framed) {
  if (!socket_ || !socket_->is_open()) return;
  boost::system::error_code ec;
  asio::write(*socket_, asio::buffer(framed), ec);
  // A client gone mid-answer: its read fails next and ends the session.
}

void SimDebugger::end_session() {
  server_.reset();
  boost::system::error_code ignored;
  if (socket_) {
    socket_->shutdown(tcp::socket::shutdown_both, ignored);
    socket_->close(ignored);
  }
  // The socket goes after any handler still queued on it has run (they see !server_).
  asio::post(acceptor_.get_executor(), [this] {
    socket_.reset();
    accept();
  });
}

}  // namespace uprog::cli
