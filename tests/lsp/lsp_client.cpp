// The tests' in-process LSP client (lsp_client.h).
#include "lsp_client.h"

namespace uprog::lsp {
namespace {

LspOptions options_with_clock(const int64_t* now) {
  LspOptions o;
  for (const dialect::Dialect* d : dialects::all()) o.dialects.push_back(d);
  o.debounce_ms = 150;
  o.now_ms = [now] { return *now; };
  return o;
}

}  // namespace

LspClient::LspClient()
    : server(options_with_clock(&now_ms), [this](const std::string& framed) {
        reader.feed(framed);
        while (auto body = reader.next()) sent.push_back(json::parse(*body));
      }) {}

std::vector<json> LspClient::raw(const std::string& text) {
  sent.clear();
  server.handle(text);
  return sent;
}

std::vector<json> LspClient::request(const std::string& method, json params) {
  return raw(
      json{{"jsonrpc", "2.0"}, {"id", next_id++}, {"method", method}, {"params", params}}.dump());
}

std::vector<json> LspClient::notify(const std::string& method, json params) {
  return raw(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", params}}.dump());
}

std::vector<json> LspClient::wait(int64_t ms) {
  sent.clear();
  now_ms += ms;
  server.poll();
  return sent;
}

json LspClient::initialize(json capabilities) {
  const std::vector<json> out = request(
      "initialize", {{"processId", nullptr}, {"rootUri", nullptr}, {"capabilities", capabilities}});
  notify("initialized");
  return out.empty() ? json() : out[0];
}

json LspClient::open(const std::string& uri, const std::string& language_id,
                     const std::string& text, int64_t version) {
  return published(notify(
      "textDocument/didOpen",
      {{"textDocument",
        {{"uri", uri}, {"languageId", language_id}, {"version", version}, {"text", text}}}}));
}

json published(const std::vector<json>& messages) {
  for (const json& m : messages)
    if (m.value("method", "") == "textDocument/publishDiagnostics") return m["params"];
  return json();
}

}  // namespace uprog::lsp
