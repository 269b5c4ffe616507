// The host's TCP or UDP client to a drive (drive_client.h).
#include "transport/drive_client.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>

#include "transport/tcp_connect.h"
#include "transport/udp_server.h"

namespace uprog::transport {

std::unique_ptr<DriveClient> DriveClient::connect(const std::string& address, std::string& error) {
  std::unique_ptr<DriveClient> client(new DriveClient());
  if (address.rfind("udp:", 0) == 0) {
    boost::asio::ip::udp::endpoint endpoint;
    if (!parse_udp_endpoint(address.substr(4), endpoint, error)) return nullptr;
    boost::system::error_code ec;
    client->udp_.open(endpoint.protocol(), ec);
    if (!ec) client->udp_.connect(endpoint, ec);
    if (ec) {
      error = "cannot reach " + address + ": " + ec.message();
      return nullptr;
    }
    return client;
  }
  if (!connect_tcp(client->io_, address, client->socket_, error)) return nullptr;
  return client;
}

void DriveClient::count_answers(const dialect::FramerOptions& framing) { framing_ = framing; }

// Sends the start line and reads until its prompt comes back (the drive prompts), or until a
// `;` line end does (the drive speaks the semicolon wire after all: `uprog sim --wire readable`).
bool DriveClient::read_prompts(const dialect::PromptWire& wire, std::chrono::milliseconds timeout) {
  std::string line = wire.start_line + "\r";
  if (::send(socket_.native_handle(), line.data(), line.size(), MSG_NOSIGNAL) !=
      static_cast<ssize_t>(line.size()))
    return false;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::string seen;
  while (true) {
    if (seen.find(wire.prompt) != std::string::npos) {
      prompted_ = true;
      reader_.read_prompts(wire);
      return true;
    }
    if (seen.find(";\r\n") != std::string::npos) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd p{socket_.native_handle(), POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count()))) <= 0) return false;
    char buffer[512];
    const ssize_t n = ::read(socket_.native_handle(), buffer, sizeof buffer);
    if (n <= 0) return false;
    seen.append(buffer, static_cast<std::size_t>(n));
  }
}

bool DriveClient::send_line(std::string_view line) {
  std::string framed(line);
  framed += framing_ || prompted_ ? "\r" : "\r\n";
  answered_ = 0;
  if (prompted_) reader_.expect_echo(line);
  if (framing_) {
    expected_ = dialect::frame_text(line, *framing_).size();
    // A comment alone gets no answer and changes nothing; its echo would only be noise.
    if (expected_ == 0) return true;
    echo_.expect(framed, framing_->semicolon_ends_line ? ";\r\n" : "\r\n");
  }
  std::string_view bytes = framed;
  while (!bytes.empty()) {
    const ssize_t n = ::send(fd(), bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

DriveClient::Wait DriveClient::read_answers(
    std::chrono::milliseconds timeout, bool until_line_end,
    const std::function<void(const Reply&)>& on_answer,
    const std::function<void(const std::string&)>& on_output) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  // Counting, a line without expressions (a comment) has nothing to wait for.
  if (until_line_end && framing_ && expected_ == 0) return Wait::kLineDone;
  while (true) {
    for (; next_ < events_.size(); ++next_) {
      const AnswerEvent& event = events_[next_];
      if (event.output) {
        if (on_output) on_output(event.reply.text);
      } else if (!event.end_of_line) {
        on_answer(event.reply);
        ++answered_;
        if (framing_ && expected_ > 0 && --expected_ == 0 && until_line_end) {
          ++next_;
          return Wait::kLineDone;
        }
      } else if (framing_ && answered_ == 0) {
        // A line end before any answer to this line closed the line before (a drive that marks
        // line ends as well as answering each expression).
      } else if (until_line_end) {
        expected_ = 0;
        ++next_;
        return Wait::kLineDone;
      }
    }
    events_.clear();
    next_ = 0;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd p{fd(), POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count()))) <= 0)
      return Wait::kTimeout;
    char buffer[65536];  // a whole reply datagram over UDP
    const ssize_t n = ::read(fd(), buffer, sizeof buffer);
    if (n <= 0) return Wait::kClosed;
    std::string answers;
    echo_.feed(std::string_view(buffer, static_cast<std::size_t>(n)), answers);
    reader_.feed(answers, events_);
  }
}

std::optional<std::vector<Reply>> DriveClient::exchange(std::string_view line,
                                                        std::chrono::milliseconds timeout,
                                                        std::string& error) {
  if (!send_line(line)) {
    error = "the drive closed the connection";
    return std::nullopt;
  }
  std::vector<Reply> replies;
  switch (read_answers(timeout, true, [&](const Reply& r) { replies.push_back(r); })) {
    case Wait::kLineDone:
      return replies;
    case Wait::kTimeout:
      error = "no answer within the timeout";
      return std::nullopt;
    case Wait::kClosed:
      error = "the drive closed the connection";
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace uprog::transport
