// Wire form of answers: writing and reading `TEXT;` and `?CODE TEXT;` (see reply.h).
#include "transport/reply.h"

#include <charconv>

namespace uprog::transport {

namespace {

void append_clean(std::string_view text, std::string& out) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    out.push_back(c == ';' || byte < 0x20 || byte == 0x7f ? ' ' : c);
  }
}

}  // namespace

void append_wire_reply(const Reply& reply, std::string& out) {
  if (reply.error != 0) {
    out.push_back('?');
    out += std::to_string(reply.error);
    if (!reply.text.empty()) out.push_back(' ');
  } else if (!reply.text.empty() && reply.text.front() == '?') {
    out.push_back(' ');  // a value never reads as an error
  }
  append_clean(reply.text, out);
  out.push_back(';');
}

std::string wire_reply(const Reply& reply) {
  std::string out;
  append_wire_reply(reply, out);
  return out;
}

Reply parse_wire_reply(std::string_view answer) {
  if (answer.empty() || answer.front() != '?') return {std::string(answer), 0};
  answer.remove_prefix(1);
  std::int32_t code = -1;
  const auto [end, ec] = std::from_chars(answer.data(), answer.data() + answer.size(), code);
  if (ec != std::errc{}) code = -1;
  answer.remove_prefix(static_cast<std::size_t>(end - answer.data()));
  if (!answer.empty() && answer.front() == ' ') answer.remove_prefix(1);
  return {std::string(answer), code};
}

}  // namespace uprog::transport
