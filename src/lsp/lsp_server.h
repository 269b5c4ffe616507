// `uprog lsp`'s protocol: a Language Server Protocol 3.17 server over the dialects' compilers.
// It takes JSON-RPC messages as texts (jsonrpc/rpc_message.h checks each) and sends responses
// and notifications, framed, through a callback; the transport (stdin and stdout, a TCP
// connection) and the wait for the debounce are the tool's. Documents are compiled in memory in
// their dialect, chosen by languageId ("gold" or "elmo-gold") or by extension.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dialect/dialect.h"
#include "lsp/analysis.h"
#include "lsp/reference_index.h"
#include "lsp/text_document.h"
#include "lsp/workspace.h"

namespace uprog::lsp {

struct LspOptions {
  std::vector<const dialect::Dialect*> dialects;  // the ones documents may be in
  // Diagnostics follow a change once no other change came for this long.
  int64_t debounce_ms = 150;
  // Milliseconds on a monotonic clock; null: std::chrono::steady_clock.
  std::function<int64_t()> now_ms;
};

class LspServer {
 public:
  // `send` gets each outgoing message, framed.
  LspServer(LspOptions options, std::function<void(const std::string&)> send);
  ~LspServer();

  // One incoming message's body.
  void handle(const std::string& message);
  // Publishes the diagnostics whose debounce has passed; the milliseconds until the next one is
  // due, or nullopt when none waits.
  std::optional<int64_t> poll();
  // After `exit`: the tool stops, with exit_code() (0 when shutdown came first, LSP 3.17).
  bool done() const { return done_; }
  int exit_code() const { return shutdown_ ? 0 : 1; }

 private:
  using json = nlohmann::json;
  struct Document {
    TextDocument text;
    std::optional<int64_t> due_ms;  // when its diagnostics are to be published
    // Its declarations (Dialect::outline: Gold's parses the text) for the features, made once
    // per text: an editor asks several features of each version.
    std::optional<std::vector<dialect::SourceSymbol>> outline;
  };

  void request(const json& id, const std::string& method, const json& params);
  void notification(const std::string& method, const json& params);
  json initialize(const json& params);
  void did_open(const json& params);
  void did_change(const json& params);
  void did_close(const json& params);
  void did_save(const json& params);
  void check_all_again();
  void check_includers(const Document& header, int64_t due_ms);
  void publish_included(const std::string& includer, std::map<std::string, json> by_file);
  void change_folders(const json& event);
  // The workspace as it is: its folders and the open documents.
  Workspace workspace() const;

  // A feature's request on an open document: its position, the document as analysed.
  json feature(const std::string& method, const json& params);
  const ReferenceIndex* reference_of(const dialect::Dialect* d);

  const dialect::Dialect* dialect_for(const std::string& language_id,
                                      const std::string& path) const;
  void publish_diagnostics(Document& doc);
  void log(int type, const std::string& message);
  void send(const std::string& body);
  int64_t now() const;

  LspOptions options_;
  std::function<void(const std::string&)> send_;
  PositionEncoding encoding_ = PositionEncoding::Utf16;
  bool initialized_ = false;
  bool shutdown_ = false;
  bool done_ = false;
  std::map<std::string, Document> documents_;  // by URI
  std::vector<std::string> folders_;           // the workspace's, as paths
  // Diagnostics in included files that are not open: by the file's URI, by the includer's.
  std::map<std::string, std::map<std::string, json>> from_includers_;
  std::map<const dialect::Dialect*, std::unique_ptr<ReferenceIndex>> references_;
  ClientSupport client_;
};

}  // namespace uprog::lsp
