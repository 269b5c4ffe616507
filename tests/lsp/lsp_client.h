// An in-process LSP client for the tests: it frames each message as an editor does, hands it to
// an LspServer, and keeps what the server sent; the server's clock is the test's.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dialects/registry.h"
#include "jsonrpc/framing.h"
#include "lsp/lsp_server.h"

namespace uprog::lsp {

using json = nlohmann::json;

struct LspClient {
  int64_t now_ms = 1000;
  int64_t next_id = 1;
  std::vector<json> sent;  // what the server sent since the last call
  jsonrpc::MessageReader reader;
  LspServer server;

  LspClient();
  // Sends a request; what the server sent in answer (the response and any notifications).
  std::vector<json> request(const std::string& method, json params = json::object());
  std::vector<json> notify(const std::string& method, json params = json::object());
  // A raw message body, as given.
  std::vector<json> raw(const std::string& text);
  // Lets `ms` pass and polls the server.
  std::vector<json> wait(int64_t ms);
  // initialize and initialized.
  json initialize(json capabilities = json::object());
  // didOpen of `text` at `uri`; the publishDiagnostics params that came (null when none).
  json open(const std::string& uri, const std::string& language_id, const std::string& text,
            int64_t version = 1);
};

// The publishDiagnostics params among `messages` (null when there is none).
json published(const std::vector<json>& messages);

}  // namespace uprog::lsp
