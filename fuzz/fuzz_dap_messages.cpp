// libFuzzer target: `uprog dap`'s message boundary (src/jsonrpc, src/debug/dap_server). The
// header line's first character chooses the registered dialect (its value modulo their count);
// with "launch" in it, the session starts by launching that dialect's sample program stopped on
// entry, so the messages reach a live debugger. Each message goes to DapServer::handle, and a
// running program gets 1 ms of virtual time after each. The server must answer in JSON, never
// crash; a launch or attach the input names reads no file and opens no connection.
#include <filesystem>
#include <fstream>

#include "debug/dap_server.h"
#include "dialects/registry.h"
#include "protocol_input.h"

namespace {

using uprog::dialect::Dialect;

// The sample of `d`, written once to a file a launch names.
const std::string& sample_path(const Dialect& d) {
  static std::vector<std::pair<const Dialect*, std::string>> written;
  for (const auto& [dialect, path] : written)
    if (dialect == &d) return path;
  const auto dir = std::filesystem::temp_directory_path() / "uprog_fuzz_dap";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / std::string(d.sample_program().file_name)).string();
  std::ofstream(path) << d.sample_program().source;
  written.emplace_back(&d, path);
  return written.back().second;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const fuzz::ProtocolInput input = fuzz::split_protocol_input(data, size);
  const auto all = dialects::all();
  const Dialect& d =
      *all[input.header.empty() ? 0 : static_cast<uint8_t>(input.header[0]) % all.size()];
  const std::string& sample = sample_path(d);
  debug::DapOptions options;
  // Only the sample: a fuzzed path could name a device that never ends.
  options.choose_dialect = [&](const std::string&, const std::string& path,
                               std::string& error) -> const Dialect* {
    if (path == sample) return &d;
    error = "the fuzz target launches its sample only";
    return nullptr;
  };
  debug::DapServer server(std::move(options), fuzz::check_sent);
  if (input.header.find("launch") != std::string_view::npos) {
    const nlohmann::json launch = {{"seq", 1},
                                   {"type", "request"},
                                   {"command", "launch"},
                                   {"arguments",
                                    {{"program", sample},
                                     {"entry", std::string(d.sample_program().entry)},
                                     {"stopOnEntry", true}}}};
    server.handle(R"({"seq":0,"type":"request","command":"initialize"})");
    server.handle(launch.dump());
    server.handle(R"({"seq":2,"type":"request","command":"configurationDone"})");
  }
  for (const std::string& message : input.messages) {
    server.handle(message);
    if (server.done()) break;
    server.poll(1'000'000);
  }
  return 0;
}
