// JSON-RPC 2.0 messages as the Language Server Protocol carries them
// (https://www.jsonrpc.org/specification, LSP 3.17 "Base Protocol"): each incoming text checked
// field by field into a request, a notification or a response, and the texts a server sends.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "jsonrpc/fields.h"

namespace uprog::jsonrpc {

// The error codes of JSON-RPC 2.0 (section 5.1) and of LSP 3.17 (ErrorCodes, LSPErrorCodes).
enum class ErrorCode : int32_t {
  ParseError = -32700,
  InvalidRequest = -32600,
  MethodNotFound = -32601,
  InvalidParams = -32602,
  InternalError = -32603,
  ServerNotInitialized = -32002,
  RequestFailed = -32803,
};

struct RpcMessage {
  enum class Kind : uint8_t {
    Request,       // id, method, params (an object or array; absent: null)
    Notification,  // method, params
    Response,      // an answer to a request the server sent: nothing here waits for one
    Invalid,       // answer with `code` and `error`, to `id` (null when it had no usable id)
    Dropped,       // a notification or response with a wrong field: no one to answer
  } kind = Kind::Dropped;
  json id;  // an integer or a string; null when unknown
  std::string method;
  json params;
  ErrorCode code = ErrorCode::InvalidRequest;
  std::string error;
};

RpcMessage parse_rpc_message(std::string_view text);

// The texts (unframed) a server sends.
std::string rpc_result(const json& id, json result);
std::string rpc_error(const json& id, ErrorCode code, std::string_view message);
std::string rpc_notification(std::string_view method, json params);

}  // namespace uprog::jsonrpc
