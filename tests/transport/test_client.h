// A plain blocking TCP or pty client for the transport's tests: POSIX sockets with poll-based
// timeouts, and the AnswerReader to split what comes back.
#pragma once
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "transport/answer_reader.h"

namespace uprog::transport::testing {

class TestClient {
 public:
  // Connects to 127.0.0.1:port.
  explicit TestClient(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      throw std::runtime_error("connect failed");
    }
  }
  // Wraps an open descriptor (a pty slave).
  struct Adopt {};
  TestClient(int fd, Adopt) : fd_(fd) {}
  ~TestClient() { close(); }
  TestClient(const TestClient&) = delete;
  TestClient& operator=(const TestClient&) = delete;

  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  void shutdown_write() { ::shutdown(fd_, SHUT_WR); }
  int fd() const { return fd_; }

  // Sends everything; false if the peer is gone.
  bool send(std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
      if (n < 0 && errno == ENOTSOCK) return write_fd(bytes);
      if (n <= 0) return false;
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  }

  // Reads until `count` answers (end-of-line marks not counted) or the timeout; returns them.
  std::vector<Reply> answers(std::size_t count, std::chrono::milliseconds timeout,
                             bool* closed = nullptr) {
    std::vector<Reply> result;
    collect(timeout, closed, [&](const AnswerEvent& event) {
      if (!event.end_of_line && !event.output) result.push_back(event.reply);
      return result.size() >= count;
    });
    return result;
  }

  // Reads until an end-of-line mark; returns the answers before it.
  std::vector<Reply> line_answers(std::chrono::milliseconds timeout = std::chrono::seconds(5)) {
    std::vector<Reply> result;
    collect(timeout, nullptr, [&](const AnswerEvent& event) {
      if (event.end_of_line) return true;
      if (!event.output) result.push_back(event.reply);
      return false;
    });
    return result;
  }

  // Reads until `count` lines the drive sent on its own have come (answers read meanwhile are
  // dropped), or the timeout; returns them.
  std::vector<std::string> output_lines(std::size_t count, std::chrono::milliseconds timeout) {
    std::vector<std::string> result;
    collect(timeout, nullptr, [&](const AnswerEvent& event) {
      if (event.output) result.push_back(event.reply.text);
      return result.size() >= count;
    });
    return result;
  }

  // True if the server closes the connection within the timeout (data before it is dropped).
  bool closed_by_peer(std::chrono::milliseconds timeout) {
    bool closed = false;
    collect(timeout, &closed, [](const AnswerEvent&) { return false; });
    return closed;
  }

  // The raw bytes the drive sends, until `count` have come or the timeout passes (no framing:
  // for byte-exact tests of a wire form).
  std::string raw(std::size_t count, std::chrono::milliseconds timeout) {
    std::string out;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (out.size() < count) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      pollfd p{fd_, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
      char buffer[8192];
      const ssize_t n = ::read(fd_, buffer, std::min(sizeof buffer, count - out.size()));
      if (n <= 0) break;
      out.append(buffer, static_cast<std::size_t>(n));
    }
    return out;
  }

 private:
  template <class Done>
  void collect(std::chrono::milliseconds timeout, bool* closed, Done done) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (true) {
      while (next_ < events_.size()) {
        if (done(events_[next_++])) return;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return;
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char buffer[8192];
      const ssize_t n = ::read(fd_, buffer, sizeof buffer);
      if (n <= 0) {
        if (closed) *closed = true;
        return;
      }
      events_.erase(events_.begin(), events_.begin() + static_cast<std::ptrdiff_t>(next_));
      next_ = 0;
      reader_.feed(std::string_view(buffer, static_cast<std::size_t>(n)), events_);
    }
  }

  bool write_fd(std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
      if (n <= 0) return false;
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  }

  int fd_ = -1;
  AnswerReader reader_;
  std::vector<AnswerEvent> events_;
  std::size_t next_ = 0;
};

}  // namespace uprog::transport::testing
