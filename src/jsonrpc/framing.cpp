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
  while (true) {
    const size_t end = buffer_.find("\r\n\r\n");
    if (end == std::string::npos) {
      if (buffer_.size() > kMaxHeaderBytes) {
        // No header ends here: the bytes are dropped, all but a header end's possible start.
        problems_.push_back("a message header longer than 4096 bytes was dropped");
        buffer_.erase(0, buffer_.size() - 3);
      }
      return std::nullopt;
    }
    std::string problem;
    const std::optional<size_t> length =
        content_length(std::string_view(buffer_).substr(0, end), problem);
    if (!length) {
      // The header is dropped and the next one read: the stream goes on.
      problems_.push_back(problem + "; the header was dropped");
      buffer_.erase(0, end + 4);
      continue;
    }
    const size_t body = end + 4;
    if (buffer_.size() - body < *length) return std::nullopt;
    std::string message = buffer_.substr(body, *length);
    buffer_.erase(0, body + *length);
    return message;
  }
}

std::vector<std::string> MessageReader::take_problems() {
  std::vector<std::string> out;
  out.swap(problems_);
  return out;
}

std::optional<size_t> MessageReader::content_length(std::string_view header, std::string& problem) {
  // Header fields, "Name: value" each ending in CR LF; only Content-Length matters.
  std::optional<size_t> length;
  size_t at = 0;
  while (at < header.size()) {
    size_t eol = header.find("\r\n", at);
    if (eol == std::string_view::npos) eol = header.size();
    const std::string_view field = header.substr(at, eol - at);
    at = eol + 2;
    const size_t colon = field.find(':');
    if (colon == std::string_view::npos) continue;
    std::string name(field.substr(0, colon));
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // Bytes dropped before a header may be left in front of its first field's name.
    if (!name.ends_with("content-length")) continue;
    std::string_view value = field.substr(colon + 1);
    while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
    while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
    size_t n = 0;
    const auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc() || p != value.data() + value.size() || value.empty()) {
      problem = "a Content-Length that is not a number";
      return std::nullopt;
    }
    length = n;
  }
  if (!length) {
    problem = "a message header without Content-Length";
    return std::nullopt;
  }
  if (*length > kMaxMessageBytes) {
    problem = "a message of " + std::to_string(*length) + " bytes, more than the 16 MiB taken";
    return std::nullopt;
  }
  return length;
}

}  // namespace uprog::jsonrpc
