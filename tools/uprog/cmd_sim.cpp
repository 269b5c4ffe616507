// `uprog sim`: the simulated drive served to hosts over TCP and/or a pseudo-terminal, its virtual
// time paced to the wall clock. Stops cleanly on SIGINT/SIGTERM. See docs/protocol.md.
#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.h"
#include "controller/controller.h"
#include "dialect_choice.h"
#include "drive_shape.h"
#include "sim_debugger.h"
#include "support/files.h"
#include "transport/controller_service.h"
#include "transport/pacer.h"
#include "transport/pty_server.h"
#include "transport/tcp_server.h"
#include "transport/udp_server.h"
#include "world_options.h"

namespace uprog::cli {

namespace {

struct SimOptions {
  std::string listen;
  bool pty = false;
  std::string udp;  // HOST:PORT of the UDP port, empty for none
  std::string state_dir;
  std::string program;
  std::string dialect;
  DriveShape shape;
  bool safe_boot = false;
  std::string wire = "drive";
  bool log = false;
  std::string dap;     // HOST:PORT of the debugger's port, empty for none
  WorldOptions world;  // --input, --switch, --analog: the world from the start
};

// Downloads `path` (a stored form such as a .upi image, or a source the dialect compiles), then
// boots the drive as a power-up would: the program loads and, unless safe boot, starts as the
// dialect starts it at power-up (Gold: AUTOEXEC, when the program has one). False with the
// reasons printed.
bool install_program(controller::Controller& drive, const SimOptions& options) {
  const std::string& path = options.program;
  if (path.ends_with(drive.dialect().stored_extension())) {
    // A stored form that is also source text (ST's macro, PUP's hand-written CUP) is checked
    // first, so that its diagnostics come before anything is stored.
    const auto sources = drive.dialect().source_extensions();
    if (std::any_of(sources.begin(), sources.end(),
                    [&](std::string_view ext) { return path.ends_with(ext); })) {
      dialect::CompileSettings check;
      check.check_only = true;
      const dialect::CompileOutput checked = drive.dialect().compile_file(path, check);
      fmt::print(stderr, "{}", format_text(checked.diagnostics));
      if (!checked.ok()) return false;
    }
    std::string error;
    const auto bytes = read_binary_file(path, &error);
    if (!bytes) {
      fmt::print(stderr, "uprog sim: {}\n", error);
      return false;
    }
    const auto result = drive.download(*bytes);
    if (!result.ok) {
      fmt::print(stderr, "uprog sim: {}: {}\n", path, result.error);
      return false;
    }
    // `uprog build`'s debug map beside the stored form (PUP: X.cup.json), for the debugger.
    if (std::filesystem::exists(path + ".json")) {
      if (const auto map = read_text_file(path + ".json", &error))
        drive.firmware().set_debug_map(*map);
    }
  } else {
    std::vector<Diagnostic> diagnostics;
    if (!drive.download_source_file(path, diagnostics)) {
      fmt::print(stderr, "{}", format_text(diagnostics));
      return false;
    }
  }
  // As at power-up: the stored program loads and starts where the dialect starts it then.
  const size_t known = drive.boot_messages().size();
  drive.reboot();
  for (size_t i = known; i < drive.boot_messages().size(); ++i) {
    fmt::print(stderr, "uprog sim: {}: {}\n", path, drive.boot_messages()[i]);
  }
  return drive.boot_messages().size() == known;
}

// With --log, what the firmware did, printed after each line and each step of time.
void print_log(controller::Controller& drive) {
  for (const auto& entry : drive.take_log()) {
    fmt::print("{:>12} us  {}\n", entry.time_us, entry.text);
    std::fflush(stdout);
  }
}

int run_sim(const SimOptions& options) {
  namespace asio = boost::asio;
  asio::ip::tcp::endpoint endpoint;
  std::string error;
  const bool listen = !options.listen.empty() || (!options.pty && options.udp.empty());
  if (listen && !transport::parse_endpoint(
                    options.listen.empty() ? "127.0.0.1:5025" : options.listen, endpoint, error)) {
    fmt::print(stderr, "uprog sim: {}\n", error);
    return 2;
  }
  controller::ControllerOptions controller_options;
  controller_options.dialect = choose_dialect(options.dialect, options.program, "sim");
  if (controller_options.dialect == nullptr) return 2;
  controller_options.state_dir = options.state_dir;
  controller_options.safe_boot = options.safe_boot;
  apply(options.shape, controller_options);
  controller_options.wire_style =
      options.wire == "readable" ? dialect::WireStyle::kReadable : dialect::WireStyle::kDrive;
  controller::Controller drive(controller_options);
  for (const auto& message : drive.boot_messages()) fmt::print(stderr, "uprog sim: {}\n", message);
  if (!options.program.empty() && !install_program(drive, options)) return 1;
  // After the program's boot: the world outlives a reboot, the drive finds it as it is.
  if (!place_world(options.world, drive, "sim")) return 2;

  transport::ControllerService service(drive, [&drive, &options] {
    if (options.log) print_log(drive);
  });
  asio::ip::tcp::endpoint dap_endpoint;
  if (!options.dap.empty() && !transport::parse_endpoint(options.dap, dap_endpoint, error)) {
    fmt::print(stderr, "uprog sim: --dap: {}\n", error);
    return 2;
  }
  asio::ip::udp::endpoint udp_endpoint;
  if (!options.udp.empty() && !transport::parse_udp_endpoint(options.udp, udp_endpoint, error)) {
    fmt::print(stderr, "uprog sim: --udp: {}\n", error);
    return 2;
  }
  asio::io_context io;
  // Taken before "listening" is printed: a host that reads that line and at once sends SIGTERM
  // gets a clean stop (the signal waits in the set until the loop below runs).
  asio::signal_set signals(io, SIGINT, SIGTERM);
  std::unique_ptr<transport::TcpServer> tcp;
  std::unique_ptr<transport::UdpServer> udp;
  std::unique_ptr<transport::PtyServer> pty;
  std::unique_ptr<SimDebugger> debugger;
  try {
    if (listen) {
      tcp = std::make_unique<transport::TcpServer>(io, service, endpoint);
      const auto where = tcp->local_endpoint();
      const auto address = where.address().to_string();
      fmt::print("listening on tcp {}:{}\n",
                 where.address().is_v6() ? "[" + address + "]" : address, where.port());
    }
    if (!options.udp.empty()) {
      udp = std::make_unique<transport::UdpServer>(io, service, udp_endpoint);
      const auto where = udp->local_endpoint();
      const auto address = where.address().to_string();
      fmt::print("listening on udp {}:{}\n",
                 where.address().is_v6() ? "[" + address + "]" : address, where.port());
    }
    if (options.pty) {
      pty = std::make_unique<transport::PtyServer>(io, service);
      fmt::print("listening on pty {}\n", pty->slave_path());
    }
    if (!options.dap.empty()) {
      debugger = std::make_unique<SimDebugger>(io, drive, service, dap_endpoint);
      const auto where = debugger->local_endpoint();
      const auto address = where.address().to_string();
      fmt::print("debugger on tcp {}:{}\n", where.address().is_v6() ? "[" + address + "]" : address,
                 where.port());
    }
  } catch (const boost::system::system_error& e) {
    fmt::print(stderr, "uprog sim: {}\n", e.what());
    return 1;
  }
  std::fflush(stdout);

  transport::Pacer pacer(io, service);
  pacer.start();
  signals.async_wait([&](const boost::system::error_code& ec, int) {
    if (ec) return;
    pacer.stop();
    if (tcp) tcp->stop();
    if (udp) udp->stop();
    if (pty) pty->stop();
    if (debugger) debugger->stop();
    io.stop();
  });
  io.run();
  fmt::print(stderr, "uprog sim: stopped at {} us of virtual time\n", drive.now_us());
  return 0;
}

void add_sim(Options& cmd, Action& action) {
  auto options = std::make_shared<SimOptions>();
  cmd.option("--listen", options->listen,
             "HOST:PORT to listen on (default 127.0.0.1:5025; port 0 picks a free one)");
  cmd.flag("--pty", options->pty, "also open a pseudo-terminal and print its path");
  cmd.option("--udp", options->udp,
             "HOST:PORT of a UDP port too: one command per datagram, one reply datagram "
             "(Elmo drives use 5001; port 0 picks a free one)");
  cmd.option("--state", options->state_dir, "folder for the stored program and parameters");
  cmd.option("--program", options->program, "source or stored form (.upi) to download and load");
  add_dialect_option(cmd, options->dialect);
  add_drive_shape_options(cmd, options->shape);
  add_world_options(cmd, options->world, /*with_inputs=*/true);
  cmd.flag("--safe-boot", options->safe_boot, "boot without running AUTOEXEC");
  cmd.option("--wire", options->wire,
             "drive: the bytes the vendor's drive sends (default); readable: error texts and a "
             "line end after each line (docs/protocol.md)")
      .one_of({"drive", "readable"});
  cmd.option("--dap", options->dap,
             "HOST:PORT: serve the debugger there, for `uprog dap`'s attach or an editor "
             "(port 0 picks one; docs/debugging.md)");
  cmd.flag("--log", options->log, "print what the firmware does (auto-routines, errors)");
  cmd.on_chosen([&action, options] { action = [options] { return run_sim(*options); }; });
}

const Subcommand kSim("sim", "Serve the simulated drive over TCP and/or a pty", add_sim);

}  // namespace
}  // namespace uprog::cli
