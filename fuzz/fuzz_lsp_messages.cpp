// libFuzzer target: `uprog lsp`'s message boundary (src/jsonrpc, src/lsp). The header line's
// first character chooses the registered dialect (its value modulo their count); with "open" in
// it, the session starts initialized with the dialect's sample program open, so requests reach
// a document. Each message goes to LspServer::handle, then the debounce clock moves on 200 ms
// and the server publishes what is due. The server must answer in JSON, never crash.
#include "dialects/registry.h"
#include "lsp/lsp_server.h"
#include "protocol_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const fuzz::ProtocolInput input = fuzz::split_protocol_input(data, size);
  const auto all = dialects::all();
  const dialect::Dialect& d =
      *all[input.header.empty() ? 0 : static_cast<uint8_t>(input.header[0]) % all.size()];
  int64_t now_ms = 0;
  lsp::LspOptions options;
  for (const dialect::Dialect* each : all) options.dialects.push_back(each);
  options.now_ms = [&now_ms] { return now_ms; };
  lsp::LspServer server(std::move(options), fuzz::check_sent);
  if (input.header.find("open") != std::string_view::npos) {
    server.handle(R"({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}})");
    const nlohmann::json open = {
        {"jsonrpc", "2.0"},
        {"method", "textDocument/didOpen"},
        {"params",
         {{"textDocument",
           {{"uri", "file:///fuzz/" + std::string(d.sample_program().file_name)},
            {"languageId", std::string(d.name())},
            {"version", 1},
            {"text", std::string(d.sample_program().source)}}}}}};
    server.handle(open.dump());
  }
  for (const std::string& message : input.messages) {
    server.handle(message);
    if (server.done()) break;
    now_ms += 200;
    server.poll();
  }
  return 0;
}
