// `uprog studio [FILE]`: write, run, watch and debug a drive program in the browser. Serves the
// page (built into the build folder, studio-page/) and its WebSockets from this process, with a
// simulated drive paced to the wall clock (src/studio/studio_app.h, docs/studio.md).
#include <fmt/core.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include "commands.h"
#include "dialect_choice.h"
#include "dialects/registry.h"
#include "studio/studio_app.h"
#include "support/files.h"
#include "transport/tcp_server.h"

namespace uprog::cli {
namespace {

struct StudioCliOptions {
  std::string file;
  std::string dialect;
  std::string listen = "127.0.0.1:8080";
  std::string page;
  bool open = false;
};

// The page's folder: --page, else the build's studio-page/ beside bin/ (build/bin/uprog finds
// build/studio-page).
std::string page_folder(const std::string& given) {
  if (!given.empty()) return given;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "studio-page";
  return (exe.parent_path().parent_path() / "studio-page").string();
}

// The browser, without waiting for it; its own output stays out of the studio's.
void open_browser(const std::string& url) {
  const pid_t pid = ::fork();
  if (pid != 0) return;
  ::execlp("xdg-open", "xdg-open", url.c_str(), static_cast<char*>(nullptr));
  ::_exit(127);
}

int run_studio(const StudioCliOptions& o) {
  studio::StudioOptions options;
  options.drive.dialect = choose_dialect(o.dialect, o.file, "studio");
  if (options.drive.dialect == nullptr) return 2;
  // Absolute, so that the page's language server finds the program's #include files beside it.
  options.drive.file = o.file.empty() ? "" : std::filesystem::absolute(o.file).string();
  if (!o.file.empty()) {
    std::string error;
    const auto text = read_text_file(o.file, &error);
    if (!text) {
      fmt::print(stderr, "uprog studio: {}\n", error);
      return 1;
    }
    options.drive.source = *text;
  }
  const auto all = dialects::all();
  options.dialects.assign(all.begin(), all.end());
  options.page_folder = page_folder(o.page);
  if (!std::filesystem::exists(options.page_folder + "/index.html")) {
    fmt::print(stderr,
               "uprog studio: no page in {} (build it: cmake --build build --target studio_page, "
               "which needs node and npm; or give --page DIR)\n",
               options.page_folder);
    return 1;
  }
  std::string error;
  if (!transport::parse_endpoint(o.listen, options.endpoint, error)) {
    fmt::print(stderr, "uprog studio: --listen {}: {}\n", o.listen, error);
    return 2;
  }
  if (!options.endpoint.address().is_loopback()) {
    fmt::print(stderr,
               "uprog studio: warning: listening on {}: anyone who reaches it can drive the "
               "simulated axis (and read the files of the page); the default is 127.0.0.1\n",
               o.listen);
  }
  boost::asio::io_context io;
  boost::asio::signal_set signals(io, SIGINT, SIGTERM);
  std::signal(SIGPIPE, SIG_IGN);
  std::unique_ptr<studio::StudioApp> app;
  try {
    app = std::make_unique<studio::StudioApp>(io, options);
  } catch (const boost::system::system_error& e) {
    fmt::print(stderr, "uprog studio: cannot listen on {}: {}\n", o.listen, e.what());
    return 1;
  }
  const auto where = app->local_endpoint();
  const std::string address = where.address().to_string();
  const std::string url = fmt::format(
      "http://{}:{}/", where.address().is_v6() ? "[" + address + "]" : address, where.port());
  fmt::print("studio on {}\n", url);
  std::fflush(stdout);
  if (o.open) open_browser(url);
  signals.async_wait([&](const boost::system::error_code& ec, int) {
    if (ec) return;
    app->stop();
    io.stop();
  });
  io.run();
  return 0;
}

void add_studio(Options& cmd, Action& action) {
  auto options = std::make_shared<StudioCliOptions>();
  cmd.option("FILE", options->file, "the program to open (its dialect by extension)");
  add_dialect_option(cmd, options->dialect);
  cmd.option("--listen", options->listen,
             "HOST:PORT to serve the page on (default 127.0.0.1:8080; port 0 picks one)");
  cmd.option("--page", options->page,
             "folder of the built page (default: the build's studio-page/)");
  cmd.flag("--open", options->open, "open the page in the browser (xdg-open)");
  cmd.on_chosen([&action, options] { action = [options] { return run_studio(*options); }; });
}

const Subcommand kStudio("studio", "Write, run, watch and debug a program in the browser",
                         add_studio);

}  // namespace
}  // namespace uprog::cli
