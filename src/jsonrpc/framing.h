// The base framing the Debug Adapter Protocol and the Language Server Protocol share:
// "Content-Length: N\r\n\r\n" and N bytes of JSON, as a byte stream delivers it, in pieces of
// any size.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace uprog::jsonrpc {

// "Content-Length: 12\r\n\r\n" + body.
std::string frame_message(std::string_view body);

class MessageReader {
 public:
  // Takes bytes as they arrive.
  void feed(std::string_view bytes) { buffer_.append(bytes); }
  // The next whole message's body; nullopt when none is complete yet. A header without a
  // Content-Length, with one that is no number or above 16 MiB, or longer than 4096 bytes is
  // dropped with a problem to report, and the stream goes on with what follows it.
  std::optional<std::string> next();
  // What was dropped since the last call, a line each.
  std::vector<std::string> take_problems();

  static constexpr size_t kMaxMessageBytes = 16u << 20;
  static constexpr size_t kMaxHeaderBytes = 4096;

 private:
  static std::optional<size_t> content_length(std::string_view header, std::string& problem);

  std::string buffer_;
  std::vector<std::string> problems_;
};

}  // namespace uprog::jsonrpc
