// The base framing the Debug Adapter Protocol and the Language Server Protocol share:
// "Content-Length: N\r\n\r\n" and N bytes of JSON, as a byte stream delivers it, in pieces of
// any size.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace uprog::jsonrpc {

// "Content-Length: 12\r\n\r\n" + body.
std::string frame_message(std::string_view body);

class MessageReader {
 public:
  // Takes bytes as they arrive.
  void feed(std::string_view bytes) { buffer_.append(bytes); }
  // The next whole message's body; nullopt when none is complete yet. A header without a
  // Content-Length, or one too large, sets error() and the reader takes nothing more.
  std::optional<std::string> next();
  const std::string& error() const { return error_; }

  static constexpr size_t kMaxMessageBytes = 16u << 20;

 private:
  std::string buffer_;
  std::string error_;
};

}  // namespace uprog::jsonrpc
