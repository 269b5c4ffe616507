// `uprog term HOST:PORT`: a terminal to a drive (`uprog sim` or anything speaking
// docs/protocol.md): sends each typed line, prints its answers one per line. libedit editing and
// history on a tty; reads stdin line by line when piped, so scripts and tests can use it.
#include <fmt/core.h>

#include <chrono>
#include <cstdlib>

#include "commands.h"
#include "dialect_choice.h"
#include "drive_link.h"
#include "transport/line_editor.h"

namespace uprog::cli {

namespace {

using transport::DriveClient;

struct TermOptions {
  std::string address;
  std::string dialect;
  double timeout_s = 5.0;
  bool fail_on_error = false;
};

int run_term(const TermOptions& options) {
  const dialect::Dialect* d = choose_dialect(options.dialect, "", "term");
  if (d == nullptr) return 2;
  std::string error;
  const auto connection = connect_to_drive(options.address, *d, error);
  if (!connection) {
    fmt::print(stderr, "uprog term: {}\n", error);
    return 1;
  }
  int errors = 0;
  // Each answer on a line of its own; errors as `?CODE TEXT`, with the dialect's text for a code
  // that came without one.
  const auto print = [&errors, d](const transport::Reply& reply) {
    if (reply.error != 0) {
      ++errors;
      fmt::print("{}\n", shown_error(*d, reply));
    } else if (!reply.text.empty()) {
      fmt::print("{}\n", reply.text);
    }
    std::fflush(stdout);
  };
  // What the drive sends on its own, marked so that it never reads as an answer.
  const auto print_output = [](const std::string& text) {
    fmt::print("<< {}\n", text);
    std::fflush(stdout);
  };
  const char* home = std::getenv("HOME");
  transport::LineEditor editor(home != nullptr ? std::string(home) + "/.uprog_history" : "");
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(options.timeout_s * 1000));
  if (editor.interactive()) fmt::print("connected to {}; Ctrl-D quits\n", options.address);
  while (true) {
    // Anything the drive sent on its own since the last line.
    if (connection->read_answers(std::chrono::milliseconds(0), false, print, print_output) ==
        DriveClient::Wait::kClosed) {
      fmt::print(stderr, "uprog term: the drive closed the connection\n");
      return 1;
    }
    const auto line = editor.read_line("> ");
    if (!line) break;
    if (line->find_first_not_of(" \t") == std::string::npos) continue;  // the drive ignores it
    if (!connection->send_line(*line)) {
      fmt::print(stderr, "uprog term: the drive closed the connection\n");
      return 1;
    }
    switch (connection->read_answers(timeout, true, print, print_output)) {
      case DriveClient::Wait::kLineDone:
        break;
      case DriveClient::Wait::kTimeout:
        fmt::print(stderr, "uprog term: no answer to '{}' within {} s\n", *line, options.timeout_s);
        if (!editor.interactive()) return 3;
        break;
      case DriveClient::Wait::kClosed:
        fmt::print(stderr, "uprog term: the drive closed the connection\n");
        return 1;
    }
  }
  return options.fail_on_error && errors > 0 ? 4 : 0;
}

void add_term(Options& cmd, Action& action) {
  auto options = std::make_shared<TermOptions>();
  cmd.option("ADDRESS", options->address,
             "HOST:PORT of the drive (uprog sim prints it); udp:HOST:PORT over UDP")
      .required();
  add_dialect_option(cmd, options->dialect);
  cmd.option("--timeout", options->timeout_s, "seconds to wait for a line's answers (default 5)");
  cmd.flag("--fail-on-error", options->fail_on_error,
           "exit with status 4 if any answer was an error");
  cmd.on_chosen([&action, options] { action = [options] { return run_term(*options); }; });
}

const Subcommand kTerm("term", "Talk to a drive over TCP (interactive, or stdin piped)", add_term);

}  // namespace
}  // namespace uprog::cli
