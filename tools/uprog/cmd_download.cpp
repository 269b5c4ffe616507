// `uprog download HOST:PORT FILE`: compiles a source (or takes a stored form such as a .upi image)
// on the host and downloads it into a running drive with its dialect's download lines (Gold: the
// DL lines of docs/protocol.md); `--load` then sends the dialect's load line (Gold: CC).
#include <fmt/core.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "bytecode/image.h"
#include "commands.h"
#include "dialect_choice.h"
#include "drive_link.h"
#include "support/files.h"

namespace uprog::cli {
namespace {

struct DownloadOptions {
  std::string address;
  std::string file;
  std::string dialect;
  bool load = false;
  double timeout_s = 10.0;
};

// What to send: FILE read as is when it is a stored form, else compiled in its dialect.
std::optional<std::vector<uint8_t>> stored_form_of(const std::string& path,
                                                   const dialect::Dialect& d) {
  if (path.ends_with(d.stored_extension())) {
    std::string error;
    auto bytes = read_binary_file(path, &error);
    if (!bytes) fmt::print(stderr, "uprog download: {}\n", error);
    return bytes;
  }
  dialect::CompileOutput r = d.compile_file(path, {});
  if (!r.diagnostics.empty()) fmt::print(stderr, "{}", format_text(r.diagnostics));
  if (!r.ok()) return std::nullopt;
  return std::move(r.stored_form);
}

// Sends `line` and expects no error; prints the drive's error otherwise.
bool send_expecting_success(transport::DriveClient& link, const dialect::Dialect& d,
                            const std::string& line, std::chrono::milliseconds timeout) {
  std::string error;
  const auto replies = link.exchange(line, timeout, error);
  if (!replies) {
    fmt::print(stderr, "uprog download: {}\n", error);
    return false;
  }
  for (const transport::Reply& r : *replies) {
    if (r.error == 0) continue;
    const std::string shown = line.size() > 40 ? line.substr(0, 40) + "..." : line;
    fmt::print(stderr, "uprog download: the drive answered {} with {}\n", shown, shown_error(d, r));
    return false;
  }
  return true;
}

int run_download(const DownloadOptions& options) {
  const dialect::Dialect* d = choose_dialect(options.dialect, options.file, "download");
  if (d == nullptr) return 2;
  const auto image = stored_form_of(options.file, *d);
  if (!image) return 1;
  if (image->empty() || image->size() > d->max_download_bytes()) {
    fmt::print(stderr, "uprog download: the program has {} bytes; a drive takes 1 to {}\n",
               image->size(), d->max_download_bytes());
    return 1;
  }
  std::string error;
  const auto client = connect_to_drive(options.address, *d, error);
  if (!client) {
    fmt::print(stderr, "uprog download: {}\n", error);
    return 1;
  }
  transport::DriveClient& link = *client;
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(options.timeout_s * 1000));
  // One line at a time: a refused chunk stops the transfer at once (the drive dropped it too).
  for (const std::string& line : d->download_lines(*image)) {
    if (!send_expecting_success(link, *d, line, timeout)) return 1;
  }
  fmt::print("downloaded {} bytes to {}\n", image->size(), options.address);
  if (options.load && !d->load_line().empty()) {
    if (!send_expecting_success(link, *d, d->load_line(), timeout)) return 1;
    fmt::print("loaded into RAM ({})\n", d->load_line());
  }
  return 0;
}

void add_download(Options& cmd, Action& action) {
  auto options = std::make_shared<DownloadOptions>();
  cmd.option("ADDRESS", options->address, "HOST:PORT of the drive (uprog sim prints it)")
      .required();
  cmd.option("FILE", options->file, "source, or a stored form such as a .upi image").required();
  add_dialect_option(cmd, options->dialect);
  cmd.flag("--load", options->load,
           "then load the program to run, with the dialect's load command");
  cmd.option("--timeout", options->timeout_s, "seconds to wait for each answer (default 10)");
  cmd.on_chosen([&action, options] { action = [options] { return run_download(*options); }; });
}

const Subcommand kDownload("download", "Download a program into a running drive (uprog sim)",
                           add_download);

}  // namespace
}  // namespace uprog::cli
