// The LSP server's lifecycle, document sync and diagnostics (lsp_server.h). The messages are
// LSP 3.17's: https://microsoft.github.io/language-server-protocol/specifications/lsp/3.17/
#include "lsp/lsp_server.h"

#include <algorithm>
#include <cctype>
#include <chrono>

#include "jsonrpc/fields.h"
#include "jsonrpc/framing.h"
#include "jsonrpc/rpc_message.h"
#include "lsp/lsp_diagnostics.h"
#include "lsp/uri.h"

namespace uprog::lsp {
namespace {

using jsonrpc::ErrorCode;

// A request that cannot be served: answered with this code and text.
struct RequestError {
  ErrorCode code;
  std::string message;
};

bool ends_with_ignoring_case(std::string_view text, std::string_view suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), text.end() - static_cast<long>(suffix.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

Position position_from(const nlohmann::json& p) {
  return {jsonrpc::required_integer(p, "line", 0), jsonrpc::required_integer(p, "character", 0)};
}

}  // namespace

LspServer::LspServer(LspOptions options, std::function<void(const std::string&)> send)
    : options_(std::move(options)), send_(std::move(send)) {}
LspServer::~LspServer() = default;

int64_t LspServer::now() const {
  if (options_.now_ms) return options_.now_ms();
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void LspServer::send(const std::string& body) { send_(jsonrpc::frame_message(body)); }

void LspServer::log(int type, const std::string& message) {
  send(jsonrpc::rpc_notification("window/logMessage", {{"type", type}, {"message", message}}));
}

void LspServer::handle(const std::string& text) {
  if (done_) return;
  const jsonrpc::RpcMessage m = jsonrpc::parse_rpc_message(text);
  switch (m.kind) {
    case jsonrpc::RpcMessage::Kind::Invalid:
      return send(jsonrpc::rpc_error(m.id, m.code, m.error));
    case jsonrpc::RpcMessage::Kind::Dropped:
    case jsonrpc::RpcMessage::Kind::Response:
      return;  // no one to answer; the server sends no request it waits on
    case jsonrpc::RpcMessage::Kind::Notification:
      try {
        notification(m.method, m.params);
      } catch (const jsonrpc::FieldError& e) {
        log(1, m.method + ": " + e.what() + "; the notification was ignored");
      }
      return;
    case jsonrpc::RpcMessage::Kind::Request:
      break;
  }
  try {
    request(m.id, m.method, m.params);
  } catch (const jsonrpc::FieldError& e) {
    send(jsonrpc::rpc_error(m.id, ErrorCode::InvalidParams, e.what()));
  } catch (const RequestError& e) {
    send(jsonrpc::rpc_error(m.id, e.code, e.message));
  } catch (const std::exception& e) {
    // A fault of the server's own: this request fails, the session goes on.
    send(jsonrpc::rpc_error(m.id, ErrorCode::InternalError, e.what()));
  }
}

void LspServer::request(const json& id, const std::string& method, const json& params) {
  if (shutdown_) throw RequestError{ErrorCode::InvalidRequest, "the server is shutting down"};
  if (method == "initialize") {
    if (initialized_) throw RequestError{ErrorCode::InvalidRequest, "initialize came twice"};
    json result = initialize(params.is_null() ? json::object() : params);
    initialized_ = true;
    return send(jsonrpc::rpc_result(id, std::move(result)));
  }
  if (!initialized_) throw RequestError{ErrorCode::ServerNotInitialized, "initialize first"};
  if (method == "shutdown") {
    shutdown_ = true;
    return send(jsonrpc::rpc_result(id, nullptr));
  }
  if (method.starts_with("textDocument/")) {
    json result;
    try {
      result = feature(method, params.is_null() ? json::object() : params);
    } catch (const FeatureError& e) {
      throw RequestError{ErrorCode::RequestFailed, e.what()};
    }
    return send(jsonrpc::rpc_result(id, std::move(result)));
  }
  throw RequestError{ErrorCode::MethodNotFound, "no method '" + method + "' here"};
}

void LspServer::notification(const std::string& method, const json& params) {
  if (method == "exit") {
    done_ = true;
    return;
  }
  if (!initialized_ || shutdown_) return;  // LSP 3.17: dropped until initialize, and after shutdown
  const json& p = params.is_null() ? json::object() : params;
  if (method == "textDocument/didOpen") return did_open(p);
  if (method == "textDocument/didChange") return did_change(p);
  if (method == "textDocument/didClose") return did_close(p);
  if (method == "textDocument/didSave") return did_save(p);
  // A header changed on disk (the client watches them): every open document is checked again.
  if (method == "workspace/didChangeWatchedFiles") return check_all_again();
  if (method == "workspace/didChangeWorkspaceFolders")
    return change_folders(jsonrpc::required_object(p, "event"));
  // initialized, $/cancelRequest, $/setTrace, workspace/didChangeConfiguration, ...: nothing to do.
}

json LspServer::initialize(const json& params) {
  using namespace jsonrpc;
  // LSP 3.17 general.positionEncodings: UTF-8 when the client offers it, else UTF-16.
  const json& general = object_or_empty(object_or_empty(params, "capabilities"), "general");
  const std::vector<std::string> encodings = strings_or_empty(general, "positionEncodings");
  encoding_ = std::find(encodings.begin(), encodings.end(), "utf-8") != encodings.end()
                  ? PositionEncoding::Utf8
                  : PositionEncoding::Utf16;
  const json& text_document =
      object_or_empty(object_or_empty(params, "capabilities"), "textDocument");
  client_.snippets =
      bool_or(object_or_empty(object_or_empty(text_document, "completion"), "completionItem"),
              "snippetSupport", false);
  client_.hierarchical_symbols = bool_or(object_or_empty(text_document, "documentSymbol"),
                                         "hierarchicalDocumentSymbolSupport", false);
  // The workspace: its folders (LSP 3.17), else the deprecated rootUri and rootPath.
  if (const json* folders = find(params, "workspaceFolders"); folders && folders->is_array()) {
    for (const json& f : *folders) {
      if (!f.is_object()) continue;
      if (std::optional<std::string> path = path_from_uri(peek_string(f, "uri").value_or("")))
        folders_.push_back(normal_path(*path));
    }
  } else if (std::optional<std::string> root =
                 path_from_uri(peek_string(params, "rootUri").value_or(""))) {
    folders_.push_back(normal_path(*root));
  } else if (const std::string root_path = peek_string(params, "rootPath").value_or("");
             !root_path.empty()) {
    folders_.push_back(normal_path(root_path));
  }
  json capabilities = {
      {"positionEncoding", encoding_ == PositionEncoding::Utf8 ? "utf-8" : "utf-16"},
      {"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", true}}},
      {"hoverProvider", true},
      {"completionProvider", {{"triggerCharacters", json::array({"#", "_"})}}},
      {"signatureHelpProvider", {{"triggerCharacters", json::array({"(", ","})}}},
      {"definitionProvider", true},
      {"referencesProvider", true},
      {"renameProvider", {{"prepareProvider", true}}},
      {"documentSymbolProvider", true},
      {"foldingRangeProvider", true},
      {"semanticTokensProvider", {{"legend", semantic_token_legend()}, {"full", true}}},
      {"workspace", {{"workspaceFolders", {{"supported", true}, {"changeNotifications", true}}}}},
  };
  return {{"capabilities", std::move(capabilities)},
          {"serverInfo", {{"name", "uprog"}, {"version", "0.1"}}}};
}

const ReferenceIndex* LspServer::reference_of(const dialect::Dialect* d) {
  if (d == nullptr) return nullptr;
  std::unique_ptr<ReferenceIndex>& index = references_[d];
  if (!index) index = std::make_unique<ReferenceIndex>(*d);
  return index.get();
}

json LspServer::feature(const std::string& method, const json& params) {
  using namespace jsonrpc;
  static const char* const kMethods[] = {
      "textDocument/hover",         "textDocument/completion",
      "textDocument/signatureHelp", "textDocument/definition",
      "textDocument/references",    "textDocument/rename",
      "textDocument/prepareRename", "textDocument/documentSymbol",
      "textDocument/foldingRange",  "textDocument/semanticTokens/full"};
  if (std::find(std::begin(kMethods), std::end(kMethods), method) == std::end(kMethods))
    throw RequestError{ErrorCode::MethodNotFound, "no method '" + method + "' here"};
  const std::string uri = required_string(required_object(params, "textDocument"), "uri");
  const auto it = documents_.find(uri);
  if (it == documents_.end())
    throw RequestError{ErrorCode::InvalidParams, "no open document " + uri};
  const TextDocument& doc = it->second.text;
  std::optional<std::vector<dialect::SourceSymbol>>& outline = it->second.outline;
  if (!outline && doc.dialect != nullptr) outline = doc.dialect->outline(doc.text);
  const Analysis analysis(doc, reference_of(doc.dialect), encoding_, outline ? &*outline : nullptr);
  const Workspace w = workspace();
  if (method == "textDocument/documentSymbol") return document_symbols(analysis, client_);
  if (method == "textDocument/foldingRange") return folding_ranges(analysis);
  if (method == "textDocument/semanticTokens/full") return semantic_tokens(analysis, w);
  const Position at = position_from(required_object(params, "position"));
  if (method == "textDocument/hover") return hover(analysis, w, at);
  if (method == "textDocument/completion") return completion(analysis, w, at, client_);
  if (method == "textDocument/signatureHelp") return signature_help(analysis, w, at);
  if (method == "textDocument/definition") return definition(analysis, w, at);
  if (method == "textDocument/references") {
    return references(analysis, w, at,
                      bool_or(object_or_empty(params, "context"), "includeDeclaration", true));
  }
  if (method == "textDocument/prepareRename") return prepare_rename(analysis, w, at);
  return rename(analysis, w, at, required_string(params, "newName"));
}

const dialect::Dialect* LspServer::dialect_for(const std::string& language_id,
                                               const std::string& path) const {
  // "gold", or a vendor's id ending in "-gold" (editors/vscode's "elmo-gold").
  for (const dialect::Dialect* d : options_.dialects) {
    const std::string name(d->name());
    if (language_id == name || ends_with_ignoring_case(language_id, "-" + name)) return d;
  }
  for (const dialect::Dialect* d : options_.dialects) {
    for (std::string_view ext : d->source_extensions())
      if (ends_with_ignoring_case(path, ext)) return d;
  }
  return nullptr;
}

void LspServer::did_open(const json& params) {
  using namespace jsonrpc;
  const json& item = required_object(params, "textDocument");
  Document doc;
  doc.text.uri = required_string(item, "uri");
  doc.text.path = path_from_uri(doc.text.uri).value_or("");
  doc.text.language_id = string_or(item, "languageId", "");
  doc.text.version = integer_or(item, "version", 0);
  doc.text.text = required_string(item, "text");
  doc.text.dialect =
      dialect_for(doc.text.language_id, doc.text.path.empty() ? doc.text.uri : doc.text.path);
  if (doc.text.dialect == nullptr) {
    log(3, "no dialect takes " + doc.text.uri + " (languageId '" + doc.text.language_id +
               "'): it is not checked");
  }
  Document& stored = documents_[doc.text.uri] = std::move(doc);
  publish_diagnostics(stored);
  check_includers(stored, now());
}

void LspServer::did_change(const json& params) {
  using namespace jsonrpc;
  const json& id = required_object(params, "textDocument");
  const auto it = documents_.find(required_string(id, "uri"));
  if (it == documents_.end()) return;  // a change to a document never opened: nothing to apply
  Document& doc = it->second;
  // Checked whole before the first edit applies: a bad change leaves the text as it was.
  const json& changes = array_or_empty(params, "contentChanges");
  for (const json& c : changes) {
    require_object(c, "contentChanges");
    (void)required_string(c, "text");
    if (const json* range = find(c, "range")) {
      (void)position_from(required_object(*range, "start"));
      (void)position_from(required_object(*range, "end"));
    }
  }
  for (const json& c : changes) {
    const std::string replacement = c["text"].get<std::string>();
    if (const json* range = find(c, "range")) {
      doc.text.replace(position_from((*range)["start"]), position_from((*range)["end"]),
                       replacement, encoding_);
    } else {
      doc.text.text = replacement;
    }
  }
  doc.outline.reset();  // made again from the new text when a feature asks
  doc.text.version = integer_or(id, "version", doc.text.version + 1);
  doc.due_ms = now() + options_.debounce_ms;
  check_includers(doc, *doc.due_ms);
}

// An open header's text, saved or not, is what the documents that include it compile with: they
// are checked again at `due_ms`.
void LspServer::check_includers(const Document& header, int64_t due_ms) {
  if (header.text.path.empty()) return;
  const Workspace w = workspace();
  const std::string changed = normal_path(header.text.path);
  for (auto& [uri, other] : documents_) {
    if (&other == &header) continue;
    const std::vector<std::string> files = w.includes_of(other.text, kIncludeDepth);
    if (std::find(files.begin(), files.end(), changed) != files.end()) other.due_ms = due_ms;
  }
}

void LspServer::did_close(const json& params) {
  const json& id = jsonrpc::required_object(params, "textDocument");
  const auto it = documents_.find(jsonrpc::required_string(id, "uri"));
  if (it == documents_.end()) return;
  check_includers(it->second, now());  // they read the file on disk again
  publish_included(it->first, {});     // what it found in its headers goes with it
  // Its diagnostics go with it (LSP 3.17: the server clears what it published).
  send(jsonrpc::rpc_notification("textDocument/publishDiagnostics",
                                 {{"uri", it->first}, {"diagnostics", json::array()}}));
  documents_.erase(it);
}

// A saved file may be a header that other open documents include: they are checked again.
void LspServer::did_save(const json& params) {
  (void)jsonrpc::required_object(params, "textDocument");
  check_all_again();
}

void LspServer::check_all_again() {
  for (auto& [uri, doc] : documents_) doc.due_ms = now();
}

// LSP 3.17 WorkspaceFoldersChangeEvent: its removed folders go, its added ones come last; the
// open documents' includes may now be found elsewhere, so they are checked again.
void LspServer::change_folders(const json& event) {
  using namespace jsonrpc;
  const auto paths_of = [&](const char* key) {
    std::vector<std::string> paths;
    for (const json& f : array_or_empty(event, key)) {
      require_object(f, key);
      if (std::optional<std::string> path = path_from_uri(required_string(f, "uri")))
        paths.push_back(normal_path(*path));
    }
    return paths;
  };
  const std::vector<std::string> removed = paths_of("removed"), added = paths_of("added");
  std::erase_if(folders_, [&](const std::string& f) {
    return std::find(removed.begin(), removed.end(), f) != removed.end();
  });
  for (const std::string& f : added)
    if (std::find(folders_.begin(), folders_.end(), f) == folders_.end()) folders_.push_back(f);
  check_all_again();
}

Workspace LspServer::workspace() const {
  std::vector<const TextDocument*> open;
  for (const auto& [uri, doc] : documents_) open.push_back(&doc.text);
  return Workspace(folders_, std::move(open));
}

std::optional<int64_t> LspServer::poll() {
  const int64_t t = now();
  std::optional<int64_t> next;
  for (auto& [uri, doc] : documents_) {
    if (!doc.due_ms) continue;
    if (*doc.due_ms <= t) {
      publish_diagnostics(doc);
    } else {
      next = std::min(next.value_or(INT64_MAX), *doc.due_ms - t);
    }
  }
  return next;
}

void LspServer::publish_diagnostics(Document& doc) {
  doc.due_ms.reset();
  if (doc.text.dialect == nullptr) return;
  const std::string compiled_as = doc.text.path.empty() ? doc.text.uri : doc.text.path;
  dialect::CompileSettings settings;
  settings.check_only = true;
  const Workspace w = workspace();
  settings.includes = w.include_search();
  json diagnostics = json::array();
  std::map<std::string, json> in_includes;
  try {
    const dialect::CompileOutput out =
        doc.text.dialect->compile_source(SourceFile{compiled_as, doc.text.text}, settings);
    diagnostics = to_lsp_diagnostics(doc.text, compiled_as, out.diagnostics, encoding_, &w);
    in_includes = included_file_diagnostics(doc.text, compiled_as, out.diagnostics, encoding_, w);
  } catch (const std::exception& e) {
    log(1, "checking " + doc.text.uri + " failed: " + e.what());
  }
  send(jsonrpc::rpc_notification("textDocument/publishDiagnostics",
                                 {{"uri", doc.text.uri},
                                  {"version", doc.text.version},
                                  {"diagnostics", std::move(diagnostics)}}));
  publish_included(doc.text.uri, std::move(in_includes));
}

// An included file that is not open shows what its includers' compiles found in it (all of
// them, each once); one that is open shows its own. A file they no longer find errors in is
// cleared.
void LspServer::publish_included(const std::string& includer, std::map<std::string, json> by_file) {
  std::vector<std::string> touched;
  for (auto& [file, by_includer] : from_includers_) {
    if (by_includer.erase(includer) > 0) touched.push_back(file);
  }
  for (auto& [file, list] : by_file) {
    from_includers_[file][includer] = std::move(list);
    if (std::find(touched.begin(), touched.end(), file) == touched.end()) touched.push_back(file);
  }
  for (const std::string& file : touched) {
    json all = json::array();
    for (const auto& [from, list] : from_includers_[file]) {
      for (const json& d : list)
        if (std::find(all.begin(), all.end(), d) == all.end()) all.push_back(d);
    }
    if (from_includers_[file].empty()) from_includers_.erase(file);
    if (documents_.count(file) > 0) continue;  // open: its own diagnostics stand
    send(jsonrpc::rpc_notification("textDocument/publishDiagnostics",
                                   {{"uri", file}, {"diagnostics", std::move(all)}}));
  }
}

}  // namespace uprog::lsp
