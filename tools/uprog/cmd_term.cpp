// `uprog term HOST:PORT`: a terminal to a drive (`uprog sim` or anything speaking docs/protocol.md):
// sends each typed line, prints its answers one per line. libedit editing and history on a tty;
// reads stdin line by line when piped, so scripts and tests can use it.
#include <fmt/core.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>

#include "commands.h"
#include "transport/answer_reader.h"
#include "transport/tcp_connect.h"
#include "transport/asio.h"
#include "transport/line_editor.h"

namespace uprog::cli {

namespace {

namespace asio = boost::asio;
using transport::AnswerEvent;

struct TermOptions {
  std::string address;
  double timeout_s = 5.0;
  bool fail_on_error = false;
};

enum class Wait { kLineDone, kTimeout, kClosed };

class Connection {
 public:
  explicit Connection(asio::ip::tcp::socket socket) : socket_(std::move(socket)) {}

  bool send(std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::send(socket_.native_handle(), bytes.data(), bytes.size(), MSG_NOSIGNAL);
      if (n <= 0) return false;
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  }

  // Prints answers as they come until the end of the current line's answers (or, with a zero
  // timeout, until nothing more is waiting). Counts error answers.
  Wait print_answers(std::chrono::milliseconds timeout, bool until_line_end) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (true) {
      for (; next_ < events_.size(); ++next_) {
        const AnswerEvent& event = events_[next_];
        if (event.end_of_line) {
          if (until_line_end) {
            ++next_;
            return Wait::kLineDone;
          }
          continue;
        }
        if (event.reply.error != 0) {
          ++errors;
          fmt::print("?{}{}{}\n", event.reply.error, event.reply.text.empty() ? "" : " ",
                     event.reply.text);
        } else if (!event.reply.text.empty()) {
          fmt::print("{}\n", event.reply.text);
        }
      }
      std::fflush(stdout);
      events_.clear();
      next_ = 0;
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      pollfd p{socket_.native_handle(), POLLIN, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
      if (ready <= 0) return Wait::kTimeout;
      char buffer[8192];
      const ssize_t n = ::read(socket_.native_handle(), buffer, sizeof buffer);
      if (n <= 0) return Wait::kClosed;
      reader_.feed(std::string_view(buffer, static_cast<std::size_t>(n)), events_);
    }
  }

  int errors = 0;

 private:
  asio::ip::tcp::socket socket_;
  transport::AnswerReader reader_;
  std::vector<AnswerEvent> events_;
  std::size_t next_ = 0;
};

bool connect(asio::io_context& io, const std::string& address, asio::ip::tcp::socket& socket) {
  std::string error;
  if (transport::connect_tcp(io, address, socket, error)) return true;
  fmt::print(stderr, "uprog term: {}\n", error);
  return false;
}

int run_term(const TermOptions& options) {
  asio::io_context io;
  asio::ip::tcp::socket socket(io);
  if (!connect(io, options.address, socket)) return 1;
  Connection connection(std::move(socket));
  const char* home = std::getenv("HOME");
  transport::LineEditor editor(home != nullptr ? std::string(home) + "/.uprog_history" : "");
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(options.timeout_s * 1000));
  if (editor.interactive()) fmt::print("connected to {}; Ctrl-D quits\n", options.address);
  while (true) {
    // Anything the drive sent on its own since the last line.
    if (connection.print_answers(std::chrono::milliseconds(0), false) == Wait::kClosed) {
      fmt::print(stderr, "uprog term: the drive closed the connection\n");
      return 1;
    }
    const auto line = editor.read_line("> ");
    if (!line) break;
    if (line->find_first_not_of(" \t") == std::string::npos) continue;  // the drive ignores it
    if (!connection.send(*line + "\n")) {
      fmt::print(stderr, "uprog term: the drive closed the connection\n");
      return 1;
    }
    switch (connection.print_answers(timeout, true)) {
      case Wait::kLineDone:
        break;
      case Wait::kTimeout:
        fmt::print(stderr, "uprog term: no answer to '{}' within {} s\n", *line, options.timeout_s);
        if (!editor.interactive()) return 3;
        break;
      case Wait::kClosed:
        fmt::print(stderr, "uprog term: the drive closed the connection\n");
        return 1;
    }
  }
  return options.fail_on_error && connection.errors > 0 ? 4 : 0;
}

void add_term(CLI::App* cmd, Action& action) {
  auto options = std::make_shared<TermOptions>();
  cmd->add_option("ADDRESS", options->address, "HOST:PORT of the drive (uprog sim prints it)")
      ->required();
  cmd->add_option("--timeout", options->timeout_s, "seconds to wait for a line's answers (default 5)");
  cmd->add_flag("--fail-on-error", options->fail_on_error,
                "exit with status 4 if any answer was an error");
  cmd->callback([&action, options] { action = [options] { return run_term(*options); }; });
}

const Subcommand kTerm("term", "Talk to a drive over TCP (interactive, or stdin piped)", add_term);

}  // namespace
}  // namespace uprog::cli
