// `uprog studio`'s server (studio_app.h).
#include "studio/studio_app.h"

#include <algorithm>

namespace uprog::studio {

std::string unframed(const std::string& framed) {
  const size_t body = framed.find("\r\n\r\n");
  return body == std::string::npos ? framed : framed.substr(body + 4);
}

StudioApp::StudioApp(boost::asio::io_context& io, StudioOptions options)
    : io_(io),
      options_(std::move(options)),
      drive_(options_.drive),
      server_(io, options_.endpoint, options_.page_folder, options_.limits),
      timer_(io) {
  server_.route("/ws/drive", [this](auto peer) { return drive_socket(peer); });
  server_.route("/ws/lsp", [this](auto peer) { return lsp_socket(peer); });
  server_.route("/ws/dap", [this](auto peer) { return dap_socket(peer); });
  drive_.set_time_keeper([this](uint64_t ns) { return debugger_ && debugger_->keep_time(ns); },
                         [this] {
                           if (debugger_) debugger_->after_host_line();
                         });
  drive_.set_program_changed([this] {
    if (debugger_) debugger_->after_host_line();
  });
  last_tick_ = last_status_ = Clock::now();
  schedule();
}

StudioApp::~StudioApp() {
  drive_.set_time_keeper({}, {});
  drive_.set_program_changed({});
  debugger_.reset();  // detaches: the program goes on as it was
}

void StudioApp::stop() {
  stopped_ = true;
  timer_.cancel();
  server_.stop();
}

WebSocketHandler StudioApp::drive_socket(const std::shared_ptr<WebSocketPeer>& peer) {
  std::weak_ptr<WebSocketPeer> weak = peer;
  drive_peers_.push_back(weak);
  const uint64_t page = drive_.connect(PageSink{[weak](const std::string& text) {
                                                  if (auto p = weak.lock()) p->send_text(text);
                                                },
                                                [weak](const std::string& bytes) {
                                                  if (auto p = weak.lock()) p->send_binary(bytes);
                                                }});
  return {[this, page](const std::string& message) { drive_.handle(page, message); },
          [this, page] { drive_.disconnect(page); }};
}

WebSocketHandler StudioApp::lsp_socket(const std::shared_ptr<WebSocketPeer>& peer) {
  std::weak_ptr<WebSocketPeer> weak = peer;
  const uint64_t id = next_language_server_++;
  lsp::LspOptions lsp_options;
  lsp_options.dialects = options_.dialects;
  language_servers_[id] =
      std::make_unique<lsp::LspServer>(lsp_options, [weak](const std::string& framed) {
        if (auto p = weak.lock()) p->send_text(unframed(framed));
      });
  return {[this, id, weak](const std::string& message) {
            const auto it = language_servers_.find(id);
            if (it == language_servers_.end()) return;
            it->second->handle(message);
            if (it->second->done()) {
              language_servers_.erase(it);
              if (auto p = weak.lock()) p->close(1000, "exit");
            }
          },
          [this, id] { language_servers_.erase(id); }};
}

// One debugging page at a time: a newer one (a reloaded page) takes over from the older.
WebSocketHandler StudioApp::dap_socket(const std::shared_ptr<WebSocketPeer>& peer) {
  end_debug_session();
  std::weak_ptr<WebSocketPeer> weak = peer;
  debug::DapOptions dap_options;
  dap_options.choose_dialect = [](const std::string&, const std::string&, std::string& error) {
    error = "the studio's debugger attaches to the program its drive runs";
    return static_cast<const dialect::Dialect*>(nullptr);
  };
  dap_options.attach_target = &drive_.controller();
  debugger_ = std::make_unique<debug::DapServer>(dap_options, [weak](const std::string& framed) {
    if (auto p = weak.lock()) p->send_text(unframed(framed));
  });
  debugger_peer_ = peer;
  const uint64_t session = ++debug_session_;  // a number: a new server may reuse the address
  return {[this, session](const std::string& message) {
            if (debug_session_ != session || !debugger_) return;  // a newer page took over
            debugger_->handle(message);
            if (debugger_->done()) end_debug_session();
          },
          [this, session] {
            if (debug_session_ == session) end_debug_session();
          }};
}

void StudioApp::end_debug_session() {
  debugger_.reset();  // detaches: the program runs on undebugged
  if (debugger_peer_) debugger_peer_->close(1000, "debug session ended");
  debugger_peer_.reset();
}

void StudioApp::schedule() {
  if (stopped_) return;
  const bool flat_out = drive_.speed() == StudioDrive::kMaxSpeed && !pages_behind();
  timer_.expires_after(flat_out ? Clock::duration::zero() : Clock::duration(kTickPeriod));
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || stopped_) return;
    tick();
    schedule();
  });
}

bool StudioApp::pages_behind() {
  std::erase_if(drive_peers_, [](const auto& weak) { return weak.expired(); });
  return std::any_of(drive_peers_.begin(), drive_peers_.end(), [](const auto& weak) {
    const auto peer = weak.lock();
    return peer && peer->queued_bytes() > kBehindBytes;
  });
}

void StudioApp::tick() {
  const auto now = Clock::now();
  const auto wall_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now - last_tick_);
  last_tick_ = now;
  drive_.tick(static_cast<uint64_t>(wall_ns.count()), pages_behind());
  for (auto& [id, server] : language_servers_) server->poll();
  if (now - last_status_ >= kStatusPeriod) {
    last_status_ = now;
    drive_.broadcast_status();
  }
}

}  // namespace uprog::studio
