// `uprog sim --dap HOST:PORT`: the drive's debugger served over TCP, one Debug Adapter Protocol
// client at a time, which attaches to the program the sim runs (docs/debugging.md, "Attaching").
// While attached, the sim's time passes through the debugger, so a stopped program stops time.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "controller/controller.h"
#include "debug/dap_server.h"
#include "jsonrpc/framing.h"
#include "transport/asio.h"
#include "transport/controller_service.h"

namespace uprog::cli {

class SimDebugger {
 public:
  // Binds and listens at once (throws boost::system::system_error if it cannot).
  SimDebugger(boost::asio::io_context& io, controller::Controller& drive,
              transport::ControllerService& service,
              const boost::asio::ip::tcp::endpoint& endpoint);
  ~SimDebugger();
  SimDebugger(const SimDebugger&) = delete;
  SimDebugger& operator=(const SimDebugger&) = delete;

  boost::asio::ip::tcp::endpoint local_endpoint() const { return acceptor_.local_endpoint(); }
  void stop();

 private:
  void accept();
  void read();
  // The client has gone or disconnected: the program runs on undebugged; the next may come.
  void end_session();
  void send(const std::string& framed);

  boost::asio::ip::tcp::acceptor acceptor_;
  controller::Controller& drive_;
  transport::ControllerService& service_;
  std::uint64_t output_listener_ = 0;
  std::unique_ptr<boost::asio::ip::tcp::socket> socket_;
  std::unique_ptr<debug::DapServer> server_;
  jsonrpc::MessageReader reader_;
  char buffer_[16384];
};

}  // namespace uprog::cli
