// The asynchronous I/O of one host connection (a TCP socket or a pty master): reads bytes, hands
// them to a HostSession, writes the answers in order. Stops reading while too much output waits
// (a host that never reads cannot make the server grow). All on the server's one thread.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "transport/asio.h"
#include "transport/host_session.h"

namespace uprog::transport {

inline constexpr std::size_t kMaxQueuedOutput = 256 * 1024;

template <class Stream>
class StreamSession : public std::enable_shared_from_this<StreamSession<Stream>> {
 public:
  StreamSession(Stream stream, LineService& service, std::function<void()> on_closed = {})
      : stream_(std::move(stream)), host_(service), on_closed_(std::move(on_closed)) {}

  void start() { read(); }

  // Text the drive sent on its own: queued behind what is already due to this host. A host
  // that reads nothing loses what exceeds the output limit rather than growing the server; once
  // there is room again, the wire may say how many texts it lost (PDL's `%L n`).
  void deliver_output(std::string_view text) {
    if (closed_) return;
    if (queued() >= kMaxQueuedOutput) {
      ++lost_;
      return;
    }
    report_lost();
    host_.deliver_output(text, pending_);
    write();
  }

  // Closes the connection at once (server shutdown).
  void close() {
    if (closed_) return;
    closed_ = true;
    host_.disconnect();
    boost::system::error_code ignored;
    stream_.close(ignored);
    if (on_closed_) on_closed_();
  }

  Stream& stream() { return stream_; }

 private:
  void read() {
    if (closed_ || reading_ || read_done_) return;
    reading_ = true;
    stream_.async_read_some(
        boost::asio::buffer(input_),
        [self = this->shared_from_this()](const boost::system::error_code& ec, std::size_t n) {
          self->on_read(ec, n);
        });
  }

  void on_read(const boost::system::error_code& ec, std::size_t n) {
    reading_ = false;
    if (closed_) return;
    if (ec) {
      // End of input, or an error: the host is gone mid-line or done. Answers already due are
      // still written (a host may half-close after its last line), then the connection closes.
      read_done_ = true;
      host_.disconnect();
      if (!writing_ && pending_.empty()) close();
      return;
    }
    host_.receive(std::string_view(input_.data(), n), pending_);
    write();
    if (queued() < kMaxQueuedOutput) read();
  }

  void write() {
    if (closed_ || writing_ || pending_.empty()) return;
    writing_ = true;
    writing_buffer_.swap(pending_);
    pending_.clear();
    boost::asio::async_write(
        stream_, boost::asio::buffer(writing_buffer_),
        [self = this->shared_from_this()](const boost::system::error_code& ec, std::size_t) {
          self->on_written(ec);
        });
  }

  void on_written(const boost::system::error_code& ec) {
    writing_ = false;
    writing_buffer_.clear();
    if (closed_) return;
    if (ec) {
      close();
      return;
    }
    if (queued() < kMaxQueuedOutput) report_lost();
    write();
    if (read_done_ && !writing_ && pending_.empty()) {
      close();
      return;
    }
    if (queued() < kMaxQueuedOutput) read();
  }

  std::size_t queued() const { return pending_.size() + writing_buffer_.size(); }

  void report_lost() {
    if (lost_ == 0) return;
    host_.deliver_lost_output(lost_, pending_);
    lost_ = 0;
  }

  Stream stream_;
  HostSession host_;
  std::function<void()> on_closed_;
  std::array<char, 4096> input_{};
  std::string pending_;
  std::string writing_buffer_;
  bool reading_ = false;
  bool writing_ = false;
  bool read_done_ = false;
  bool closed_ = false;
  std::uint64_t lost_ = 0;  // texts dropped since the host last had room
};

}  // namespace uprog::transport
