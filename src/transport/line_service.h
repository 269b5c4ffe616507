// What a transport needs from the drive behind it: answer one host line, advance virtual time,
// the drive's wire form, and the text it sends on its own. The controller adapter implements
// it; tests use fakes. Called from one thread only.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string_view>
#include <vector>

#include "dialect/wire_form.h"
#include "transport/reply.h"

namespace uprog::transport {

// One host's lines, for a service that keeps state per host (a download in progress). The
// host's session owns it and drops it when the host goes away.
class LineChannel {
 public:
  virtual ~LineChannel() = default;
  virtual std::vector<Reply> handle_line(std::string_view line) = 0;
};

class LineService {
 public:
  using OutputListener = std::function<void(std::string_view text)>;

  virtual ~LineService() = default;
  // One command line, without its terminator; the answers in order (none for a silent line).
  virtual std::vector<Reply> handle_line(std::string_view line) = 0;
  // Lets `us` microseconds of virtual time pass.
  virtual void advance(std::uint32_t us) = 0;
  // A channel for a host that has just connected; nullptr (the default): every host's lines go
  // to handle_line() alike.
  virtual std::unique_ptr<LineChannel> open_channel() { return nullptr; }
  // How the drive frames lines and writes answers.
  virtual const dialect::WireForm& wire() const = 0;

  // Every text the drive sends on its own goes to each listener (a server, for its hosts).
  std::uint64_t add_output_listener(OutputListener listener) {
    listeners_[next_listener_] = std::move(listener);
    return next_listener_++;
  }
  void remove_output_listener(std::uint64_t id) { listeners_.erase(id); }

 protected:
  void publish_output(std::string_view text) {
    for (auto& [id, listener] : listeners_) listener(text);
  }

 private:
  std::map<std::uint64_t, OutputListener> listeners_;
  std::uint64_t next_listener_ = 0;
};

}  // namespace uprog::transport
