// JSON-RPC 2.0 message checks (rpc_message.h).
#include "jsonrpc/rpc_message.h"

namespace uprog::jsonrpc {
namespace {

RpcMessage invalid(json id, ErrorCode code, std::string error) {
  RpcMessage m;
  m.kind = RpcMessage::Kind::Invalid;
  m.id = std::move(id);
  m.code = code;
  m.error = std::move(error);
  return m;
}

}  // namespace

RpcMessage parse_rpc_message(std::string_view text) {
  json m;
  std::string why;
  // JSON-RPC 2.0 section 5: a parse error, or a text that is no request object, is answered
  // with a null id, since no id can be read from it.
  if (!parse_message(text, m, why)) return invalid(nullptr, ErrorCode::ParseError, why);
  if (!m.is_object()) {
    return invalid(nullptr, ErrorCode::InvalidRequest,
                   "a message must be a JSON object (batches are not part of LSP)");
  }
  const json* id = find(m, "id");
  const bool id_usable = id != nullptr && (id->is_number_integer() || id->is_string());
  const json* method = find(m, "method");
  if (method == nullptr) {
    // An answer from the client to a request of the server's: the server sends none it waits on.
    RpcMessage r;
    r.kind = (m.contains("result") || m.contains("error")) ? RpcMessage::Kind::Response
                                                           : RpcMessage::Kind::Dropped;
    if (r.kind == RpcMessage::Kind::Dropped && id_usable)
      return invalid(*id, ErrorCode::InvalidRequest, "a request needs a \"method\"");
    return r;
  }
  const json reply_to = id_usable ? *id : json(nullptr);
  if (id != nullptr && !id_usable)
    return invalid(nullptr, ErrorCode::InvalidRequest, "\"id\" must be an integer or a string");
  const std::optional<std::string> version = peek_string(m, "jsonrpc");
  const json* params = find(m, "params");
  why.clear();
  if (version != "2.0")
    why = "\"jsonrpc\" must be \"2.0\"";
  else if (!method->is_string())
    why = "\"method\" must be a string";
  else if (params != nullptr && !params->is_object() && !params->is_array())
    why = "\"params\" must be an object or an array";
  if (!why.empty()) {
    if (!id_usable) {
      RpcMessage dropped;  // a notification: no one to answer
      dropped.error = why;
      return dropped;
    }
    return invalid(reply_to, ErrorCode::InvalidRequest, why);
  }
  RpcMessage r;
  r.kind = id_usable ? RpcMessage::Kind::Request : RpcMessage::Kind::Notification;
  r.id = reply_to;
  r.method = method->get<std::string>();
  if (params != nullptr) r.params = std::move(m["params"]);
  return r;
}

std::string rpc_result(const json& id, json result) {
  return to_text({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

std::string rpc_error(const json& id, ErrorCode code, std::string_view message) {
  return to_text({{"jsonrpc", "2.0"},
                  {"id", id},
                  {"error", {{"code", static_cast<int32_t>(code)}, {"message", message}}}});
}

std::string rpc_notification(std::string_view method, json params) {
  return to_text({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

}  // namespace uprog::jsonrpc
