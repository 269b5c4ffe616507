// `uprog studio`'s server: the studio's drive (studio_drive.h), its page and three WebSockets
// from one Beast server (web_server.h): /ws/drive (the drive's messages), /ws/lsp (the language
// server, in process, one per page) and /ws/dap (the debugger, attached to the studio's drive, one
// page at a time). A timer paces the drive to the wall clock. docs/studio.md.
#pragma once
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "debug/dap_server.h"
#include "lsp/lsp_server.h"
#include "studio/studio_drive.h"
#include "studio/web_server.h"

namespace uprog::studio {

struct StudioOptions {
  StudioDriveOptions drive;
  std::vector<const dialect::Dialect*> dialects;  // the language server's
  std::string page_folder;
  boost::asio::ip::tcp::endpoint endpoint;
  WebLimits limits;
};

class StudioApp {
 public:
  // The wall-clock pacing's period (as fast as it goes: no wait between steps).
  static constexpr auto kTickPeriod = std::chrono::milliseconds(10);
  static constexpr auto kStatusPeriod = std::chrono::milliseconds(100);
  // A drive page with more than this queued is behind: "as fast as possible" waits for it at
  // the wall clock's pace (a browser would otherwise be dropped at WebLimits' unread limit).
  static constexpr size_t kBehindBytes = size_t{1} << 20;

  // Binds and listens at once (throws boost::system::system_error if it cannot).
  StudioApp(boost::asio::io_context& io, StudioOptions options);
  ~StudioApp();
  boost::asio::ip::tcp::endpoint local_endpoint() const { return server_.local_endpoint(); }
  StudioDrive& drive() { return drive_; }
  void stop();

 private:
  using Clock = std::chrono::steady_clock;
  WebSocketHandler drive_socket(const std::shared_ptr<WebSocketPeer>& peer);
  WebSocketHandler lsp_socket(const std::shared_ptr<WebSocketPeer>& peer);
  WebSocketHandler dap_socket(const std::shared_ptr<WebSocketPeer>& peer);
  void end_debug_session();
  void schedule();
  void tick();
  bool pages_behind();

  boost::asio::io_context& io_;
  StudioOptions options_;
  StudioDrive drive_;
  WebServer server_;
  boost::asio::steady_timer timer_;
  Clock::time_point last_tick_;
  Clock::time_point last_status_;
  std::vector<std::weak_ptr<WebSocketPeer>> drive_peers_;
  std::map<uint64_t, std::unique_ptr<lsp::LspServer>> language_servers_;
  uint64_t next_language_server_ = 1;
  std::unique_ptr<debug::DapServer> debugger_;
  std::shared_ptr<WebSocketPeer> debugger_peer_;
  uint64_t debug_session_ = 0;  // the current debugging page's number
  bool stopped_ = false;
};

// The body of a framed message ("Content-Length: N\r\n\r\nbody"): what a WebSocket carries.
std::string unframed(const std::string& framed);

}  // namespace uprog::studio
