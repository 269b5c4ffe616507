// An in-process drive server for the transport's tests: a FakeService behind a TCP server (and a
// pty when asked) with the wall-clock pacer, run on its own thread as `uprog sim` runs them.
#pragma once
#include <future>
#include <memory>
#include <thread>

#include "fake_service.h"
#include "transport/pacer.h"
#include "transport/pty_server.h"
#include "transport/tcp_server.h"

namespace uprog::transport::testing {

class ServerFixture {
 public:
  explicit ServerFixture(bool with_pty = false) {
    tcp_ = std::make_unique<TcpServer>(
        io_, service_,
        boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
    if (with_pty) pty_ = std::make_unique<PtyServer>(io_, service_);
    pacer_.start();
    thread_ = std::thread([this] { io_.run(); });
  }

  std::uint16_t port() const { return tcp_->local_endpoint().port(); }
  const std::string& pty_path() const { return pty_->slave_path(); }

  // Runs `f` on the server's thread and returns its result.
  template <class F>
  auto on_server(F f) {
    std::packaged_task<decltype(f())()> task(std::move(f));
    auto result = task.get_future();
    boost::asio::post(io_, [&task] { task(); });
    return result.get();
  }
  std::size_t session_count() {
    return on_server([this] { return tcp_->session_count(); });
  }
  // The drive sends `text` on its own, to every host.
  void emit(std::string text) {
    on_server([this, text] {
      service_.emit(text);
      return 0;
    });
  }
  // Texts `first` … `first + count - 1` (`text N`), sent one after another in one turn of the
  // server's thread, so that no host can read between them.
  void emit_numbered(int first, int count) {
    on_server([this, first, count] {
      for (int i = first; i < first + count; ++i) service_.emit("text " + std::to_string(i));
      return 0;
    });
  }
  // The wire counts the texts a host lost (`%L n`); before any host connects.
  void count_lost_output() {
    on_server([this] { return service_.counts_lost = true; });
  }
  std::uint64_t lines_handled() {
    return on_server([this] { return service_.lines; });
  }

  ~ServerFixture() {
    on_server([this] {
      pacer_.stop();
      tcp_->stop();
      if (pty_) pty_->stop();
    });
    thread_.join();
  }

 private:
  FakeService service_;  // outlives the io_context, whose pending handlers hold sessions
  boost::asio::io_context io_;
  Pacer pacer_{io_, service_};
  std::unique_ptr<TcpServer> tcp_;
  std::unique_ptr<PtyServer> pty_;
  std::thread thread_;
};

}  // namespace uprog::transport::testing
