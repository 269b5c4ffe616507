// `uprog dap`: a Debug Adapter Protocol server (src/debug/dap_server.h) on stdin and stdout, or on
// one TCP connection with --listen HOST:PORT. It runs the launched program in this process; while
// the program runs, requests are read between slices of virtual time. An `attach` connects to a
// `uprog sim --dap` and relays the session to the debugger there.
#include <fmt/core.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>

#include "commands.h"
#include "debug/dap_server.h"
#include "dialects/registry.h"
#include "jsonrpc/fields.h"
#include "jsonrpc/framing.h"
#include "stream_server.h"
#include "transport/asio.h"
#include "transport/tcp_connect.h"

namespace uprog::cli {
namespace {

// Virtual time per slice while running as fast as it can: requests are read between slices.
constexpr uint64_t kSliceNs = 10'000'000;

const dialect::Dialect* dialect_for(const std::string& name, const std::string& path,
                                    std::string& error) {
  if (!name.empty()) {
    const dialect::Dialect* d = dialects::find(name);
    if (d == nullptr) error = "no dialect named '" + name + "' (uprog dialects lists them)";
    return d;
  }
  if (const dialect::Dialect* d = dialects::for_file(path)) return d;
  return &dialects::default_dialect();
}

// The connection of an attached session to a `uprog sim --dap`: the client's messages go there,
// its messages come back with this session's sequence numbers.
struct Remote {
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket socket{io};
  jsonrpc::MessageReader reader;
  int fd() { return socket.is_open() ? socket.native_handle() : -1; }
};

bool connect_remote(Remote& remote, const std::string& host, uint16_t port, std::string& error) {
  const std::string where = host.find(':') != std::string::npos
                                ? "[" + host + "]:" + std::to_string(port)
                                : host + ":" + std::to_string(port);
  return transport::connect_tcp(remote.io, where, remote.socket, error);
}

// What the sim sent: on to the client, renumbered; the answer to the replayed initialize was
// the client's long ago and is dropped. False when the sim has closed the session.
bool relay_from_remote(Remote& remote, debug::DapServer& server, int out, bool& broken) {
  char buffer[65536];
  const ssize_t n = ::read(remote.fd(), buffer, sizeof buffer);
  if (n <= 0) return false;
  remote.reader.feed(std::string_view(buffer, static_cast<size_t>(n)));
  while (auto message = remote.reader.next()) {
    nlohmann::json m;
    std::string why;
    if (!jsonrpc::parse_message(*message, m, why) || !m.is_object()) continue;
    if (jsonrpc::peek_string(m, "type") == "response" &&
        jsonrpc::peek_string(m, "command") == "initialize")
      continue;
    m["seq"] = server.next_seq();
    broken = broken || !write_all(out, jsonrpc::frame_message(jsonrpc::to_text(m)));
  }
  for (const std::string& problem : remote.reader.take_problems())
    fmt::print(stderr, "uprog dap: from the sim: {}\n", problem);
  return true;
}

// Serves one client on `in` and `out` until it disconnects or closes its end.
int serve(int in, int out) {
  std::signal(SIGPIPE, SIG_IGN);  // a client gone mid-answer ends the session, not the process
  bool broken = false;
  Remote remote;
  debug::DapOptions options;
  options.choose_dialect = dialect_for;
  options.connect_remote = [&remote](const std::string& host, uint16_t port, std::string& error) {
    return connect_remote(remote, host, port, error);
  };
  debug::DapServer server(std::move(options),
                          [&](const std::string& m) { broken = broken || !write_all(out, m); });
  jsonrpc::MessageReader reader;
  char buffer[65536];
  auto last = std::chrono::steady_clock::now();
  while (!server.done() && !broken) {
    // Running: look for requests without waiting (realtime: wait a millisecond of wall time).
    pollfd p[2] = {{in, POLLIN, 0}, {remote.fd(), POLLIN, 0}};
    const int timeout = server.running() ? (server.realtime() ? 1 : 0) : -1;
    const int ready = ::poll(p, remote.fd() < 0 ? 1 : 2, timeout);
    if (ready < 0 && errno != EINTR) return 1;
    if (ready > 0 && remote.fd() >= 0 && (p[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      if (!relay_from_remote(remote, server, out, broken)) break;  // the sim ended the session
    }
    if (ready > 0 && (p[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      const ssize_t n = ::read(in, buffer, sizeof buffer);
      if (n <= 0) break;  // the client closed its end
      reader.feed(std::string_view(buffer, static_cast<size_t>(n)));
      while (auto message = reader.next()) {
        if (server.relaying()) {
          if (!write_all(remote.fd(), jsonrpc::frame_message(*message))) return 1;
          continue;
        }
        server.handle(*message);
        for (const std::string& first : server.relay_start()) {
          if (!write_all(remote.fd(), jsonrpc::frame_message(first))) return 1;
        }
      }
      for (const std::string& problem : reader.take_problems())
        fmt::print(stderr, "uprog dap: {}\n", problem);
    }
    if (server.running()) {
      const auto now = std::chrono::steady_clock::now();
      const auto wall_ns = static_cast<uint64_t>(
          std::chrono::duration_cast<std::chrono::nanoseconds>(now - last).count());
      last = now;
      server.poll(server.realtime() ? wall_ns : kSliceNs);
    } else {
      last = std::chrono::steady_clock::now();
    }
  }
  return broken ? 1 : 0;
}

void add_options(Options& cmd, Action& action) {
  auto listen = std::make_shared<std::string>();
  cmd.option("--listen", *listen,
             "HOST:PORT: serve one client over TCP instead of stdin/stdout (port 0 picks one)");
  cmd.on_chosen([&action, listen] {
    action = [listen] {
      return listen->empty() ? serve(STDIN_FILENO, STDOUT_FILENO)
                             : serve_one_tcp_client("uprog dap", *listen, serve);
    };
  });
}

const Subcommand kDap{
    "dap", "Debug a program in an editor: a Debug Adapter Protocol server (docs/debugging.md)",
    add_options};

}  // namespace
}  // namespace uprog::cli
