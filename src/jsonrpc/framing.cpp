// Content-Length framing (framing.h).
#include "jsonrpc/framing.h"

#include <cctype>
#include <charconv>

namespace uprog::jsonrpc {

std::string frame_message(std::string_view body) {
  std::string out = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n";
  out.append(body);
  return out;
}

std::optional<std::string> MessageReader::next() {
  if (!error_.empty()) return std::nullopt;
  const size_t end = buffer_.find("\r\n\r\n");
  if (end == std::string::npos) {
    if (buffer_.size() > 4096) error_ = "a message header longer than 4096 bytes";
    return std::nullopt;
  }
  // Header fields, "Name: value" each ending in CR LF; only Content-Length matters.
  std::optional<size_t> length;
  size_t at = 0;
  while (at < end) {
    size_t eol = buffer_.find("\r\n", at);
    if (eol == std::string::npos || eol > end) eol = end;
    const std::string_view field(buffer_.data() + at, eol - at);
    const size_t colon = field.find(':');
    if (colon != std::string_view::npos) {
      std::string name(field.substr(0, colon));
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      std::string_view value = field.substr(colon + 1);
      while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
      if (name == "content-length") {
        size_t n = 0;
        const auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
        if (ec != std::errc() || p != value.data() + value.size()) {
          error_ = "a Content-Length that is not a number";
          return std::nullopt;
        }
        length = n;
      }
    }
    at = eol + 2;
  }
  if (!length) {
    error_ = "a message header without Content-Length";
    return std::nullopt;
  }
  if (*length > kMaxMessageBytes) {
    error_ = "a message of " + std::to_string(*length) + " bytes, more than the 16 MiB taken";
    return std::nullopt;
  }
  const size_t body = end + 4;
  if (buffer_.size() - body < *length) return std::nullopt;
  std::string message = buffer_.substr(body, *length);
  buffer_.erase(0, body + *length);
  return message;
}

}  // namespace uprog::jsonrpc
