// `uprog lsp`: a Language Server Protocol server (src/lsp/lsp_server.h) on stdin and stdout, or on
// one TCP connection with --listen HOST:PORT, for every registered dialect. Between messages it
// waits no longer than the next debounced diagnostics are due.
#include <fmt/core.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <memory>

#include "commands.h"
#include "dialects/registry.h"
#include "jsonrpc/framing.h"
#include "lsp/lsp_server.h"
#include "stream_server.h"

namespace uprog::cli {
namespace {

// Serves one client on `in` and `out` until it sends exit or closes its end.
int serve_lsp(int in, int out) {
  std::signal(SIGPIPE, SIG_IGN);  // a client gone mid-answer ends the session, not the process
  bool broken = false;
  lsp::LspOptions options;
  for (const dialect::Dialect* d : dialects::all()) options.dialects.push_back(d);
  lsp::LspServer server(std::move(options),
                        [&](const std::string& m) { broken = broken || !write_all(out, m); });
  jsonrpc::MessageReader reader;
  char buffer[65536];
  while (!server.done() && !broken) {
    const std::optional<int64_t> due = server.poll();
    pollfd p = {in, POLLIN, 0};
    const int ready = ::poll(&p, 1, due ? static_cast<int>(std::min<int64_t>(*due, 60'000)) : -1);
    if (ready < 0 && errno != EINTR) return 1;
    if (ready <= 0 || (p.revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
    const ssize_t n = ::read(in, buffer, sizeof buffer);
    if (n <= 0) return 1;  // the client closed its end without exit (LSP 3.17: exit code 1)
    reader.feed(std::string_view(buffer, static_cast<size_t>(n)));
    while (auto message = reader.next()) server.handle(*message);
    for (const std::string& problem : reader.take_problems())
      fmt::print(stderr, "uprog lsp: {}\n", problem);
  }
  return broken ? 1 : server.exit_code();
}

void add_lsp(Options& cmd, Action& action) {
  auto listen = std::make_shared<std::string>();
  cmd.option("--listen", *listen,
             "HOST:PORT: serve one client over TCP instead of stdin/stdout (port 0 picks one)");
  // VS Code's language client passes --stdio to a server it starts over stdio: the default here.
  auto stdio = std::make_shared<bool>(false);
  cmd.flag("--stdio", *stdio, "Serve over stdin/stdout (the default)");
  cmd.on_chosen([&action, listen, stdio] {  // holds both for the parse
    (void)stdio;
    action = [listen] {
      return listen->empty() ? serve_lsp(STDIN_FILENO, STDOUT_FILENO)
                             : serve_one_tcp_client("uprog lsp", *listen, serve_lsp);
    };
  });
}

const Subcommand kLsp{"lsp",
                      "Check programs as you type in an editor: a Language Server Protocol server "
                      "(docs/editors.md)",
                      add_lsp};

}  // namespace
}  // namespace uprog::cli
