// A host's connection to a drive over TCP, or UDP with `udp:HOST:PORT` (a `uprog sim`, or anything
// speaking the semicolon wire of docs/protocol.md): send a line, read its answers up to the
// line's end mark. The one client `uprog term`, `uprog download` and the tests' host scripts share.
#pragma once
#include <boost/asio/ip/udp.hpp>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/line_framer.h"
#include "transport/answer_reader.h"
#include "transport/asio.h"
#include "transport/echo_filter.h"

namespace uprog::transport {

class DriveClient {
 public:
  enum class Wait { kLineDone, kTimeout, kClosed };

  // Connects to "HOST:PORT" or "[V6]:PORT" over TCP, "udp:HOST:PORT" over UDP (a line a
  // datagram, an answer datagram back: udp_server.h); nullptr with `error` set when it cannot.
  static std::unique_ptr<DriveClient> connect(const std::string& address, std::string& error);

  // For a drive that marks no line ends (Gold's drive form): lines end with CR, each line's
  // answers are counted by splitting it as `framing` says, and an echo is taken out of them.
  void count_answers(const dialect::FramerOptions& framing);
  // For a drive that ends each line's answers with a prompt (dialect::PromptWire): lines end
  // with CR; sends the wire's start line and waits for its prompt. False when none came.
  bool read_prompts(const dialect::PromptWire& wire, std::chrono::milliseconds timeout);
  // Sends `line` and CR LF (CR alone when counting, and nothing for a line of comments alone);
  // false when the drive has gone.
  bool send_line(std::string_view line);
  // Hands each answer to `on_answer` as it comes, until the answers to one line have all come
  // (`until_line_end`), or until nothing more arrives within `timeout`. Lines the drive sends on
  // its own go to `on_output` (dropped without one).
  Wait read_answers(std::chrono::milliseconds timeout, bool until_line_end,
                    const std::function<void(const Reply&)>& on_answer,
                    const std::function<void(const std::string&)>& on_output = {});
  // One line and all its answers; nullopt with `error` set when the drive is gone or silent.
  std::optional<std::vector<Reply>> exchange(std::string_view line,
                                             std::chrono::milliseconds timeout, std::string& error);

 private:
  DriveClient() : socket_(io_), udp_(io_) {}
  int fd() { return udp_.is_open() ? udp_.native_handle() : socket_.native_handle(); }

  boost::asio::io_context io_;
  boost::asio::ip::tcp::socket socket_;
  boost::asio::ip::udp::socket udp_;  // open instead of socket_ for a udp: address
  AnswerReader reader_;
  std::vector<AnswerEvent> events_;
  std::size_t next_ = 0;
  std::optional<dialect::FramerOptions> framing_;  // set: answers are counted
  bool prompted_ = false;                          // the drive ends each line with a prompt
  EchoFilter echo_;
  std::size_t expected_ = 0;  // answers the line sent last still has to get, when counting
  std::size_t answered_ = 0;  // answers it got so far
};

}  // namespace uprog::transport
