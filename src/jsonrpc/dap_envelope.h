// The envelope of a Debug Adapter Protocol message as a server takes it: a request
// ({"seq": integer, "type": "request", "command": string, "arguments"?: object}) checked field by
// field before anything reads it. A request whose fields are wrong gets a failed response; a
// message that is not a request at all has no one to answer and is dropped.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "jsonrpc/fields.h"

namespace uprog::jsonrpc {

struct DapEnvelope {
  enum class Kind : uint8_t {
    Request,     // well formed: seq, command and arguments may be read
    BadRequest,  // "type": "request" with a wrong field: answer with `error`
    NotRequest,  // not JSON, not an object, or no "type": "request": drop it (`error` says why)
  } kind = Kind::NotRequest;
  int64_t seq = 0;      // the request's seq; 0 when it had none that is an integer
  std::string command;  // "" when it had none that is a string
  std::string error;
  json message;  // the parsed message (Request: an object whose "arguments" is an object)
};

DapEnvelope check_dap_message(std::string_view text);

// A failed response to request `seq` (`command` as the request named it), DAP's form: success
// false, the message, and body.error as the specification's Message.
json dap_error_response(int64_t response_seq, int64_t request_seq, std::string_view command,
                        std::string_view message);

}  // namespace uprog::jsonrpc
