// What the protocol fuzz targets (fuzz_dap_messages, fuzz_lsp_messages) share: an input is a
// header line, then the messages, either as one byte stream of Content-Length frames (when the
// rest starts with "Content-Length") fed in chunks the header's length chooses, or one message
// body per line. Every message the server sends must be a framed JSON object: anything else
// aborts, as a crash would.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "jsonrpc/framing.h"

namespace uprog::fuzz {

struct ProtocolInput {
  std::string_view header;            // the first line: the target's own choices
  std::vector<std::string> messages;  // the bodies, in order
  size_t dropped_headers = 0;         // headers the framing dropped (the stream went on)
};

inline ProtocolInput split_protocol_input(const uint8_t* data, size_t size) {
  ProtocolInput in;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const size_t eol = all.find('\n');
  in.header = all.substr(0, eol);
  const std::string_view rest = eol == std::string_view::npos ? "" : all.substr(eol + 1);
  if (rest.starts_with("Content-Length")) {
    jsonrpc::MessageReader reader;
    const size_t chunk = 1 + in.header.size() % 64;
    for (size_t at = 0; at < rest.size(); at += chunk) {
      reader.feed(rest.substr(at, chunk));
      while (auto m = reader.next()) in.messages.push_back(std::move(*m));
    }
    in.dropped_headers = reader.take_problems().size();
    return in;
  }
  size_t at = 0;
  while (at < rest.size()) {
    const size_t end = rest.find('\n', at);
    in.messages.emplace_back(rest.substr(at, end == std::string_view::npos ? end : end - at));
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  return in;
}

// Checks one framed message the server sent.
inline void check_sent(const std::string& framed) {
  jsonrpc::MessageReader reader;
  reader.feed(framed);
  const auto body = reader.next();
  if (!body || !reader.take_problems().empty()) std::abort();
  const nlohmann::json m = nlohmann::json::parse(*body, nullptr, false);
  if (!m.is_object()) std::abort();
}

}  // namespace uprog::fuzz
