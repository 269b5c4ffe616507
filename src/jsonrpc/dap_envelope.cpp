// DAP envelope checks (dap_envelope.h). The fields are the specification's ProtocolMessage and
// Request: https://microsoft.github.io/debug-adapter-protocol/specification#Base_Protocol
#include "jsonrpc/dap_envelope.h"

namespace uprog::jsonrpc {

DapEnvelope check_dap_message(std::string_view text) {
  DapEnvelope e;
  std::string why;
  if (!parse_message(text, e.message, why)) {
    e.error = why;
    e.message = nullptr;
    return e;
  }
  const std::optional<std::string> type = peek_string(e.message, "type");
  if (!e.message.is_object() || type != "request") {
    e.error = "a message that is not a request was ignored";
    return e;
  }
  const json* seq = find(e.message, "seq");
  const json* command = find(e.message, "command");
  const json* arguments = find(e.message, "arguments");
  e.kind = DapEnvelope::Kind::BadRequest;
  if (seq != nullptr && seq->is_number_integer()) {
    e.seq = seq->is_number_unsigned() && seq->get<uint64_t>() > INT64_MAX ? 0 : seq->get<int64_t>();
  }
  if (command != nullptr && command->is_string()) e.command = command->get<std::string>();
  if (seq == nullptr || !seq->is_number_integer()) {
    e.error = "a request's \"seq\" must be an integer";
  } else if (command == nullptr || !command->is_string()) {
    e.error = "a request's \"command\" must be a string";
  } else if (arguments != nullptr && !arguments->is_object()) {
    e.error = "a request's \"arguments\" must be an object";
  } else {
    e.kind = DapEnvelope::Kind::Request;
    if (arguments == nullptr) e.message["arguments"] = json::object();
    e.message["seq"] = e.seq;  // one above INT64_MAX read as 0, as the answers name it
  }
  return e;
}

json dap_error_response(int64_t response_seq, int64_t request_seq, std::string_view command,
                        std::string_view message) {
  return {{"seq", response_seq},
          {"type", "response"},
          {"request_seq", request_seq},
          {"success", false},
          {"command", command},
          {"message", message},
          {"body", {{"error", {{"id", 1}, {"format", message}}}}}};
}

}  // namespace uprog::jsonrpc
