// One answer of the drive to a host line, and how it is written on the wire: `TEXT;` for a value
// (empty for a line with no value), `?CODE TEXT;` for an error. See docs/protocol.md.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace uprog::transport {

struct Reply {
  std::string text;     // the value as the drive prints it, or the error's text (may be empty)
  std::int32_t error = 0;  // 0 for a value; the interpreter's (or the transport's) error code

  friend bool operator==(const Reply&, const Reply&) = default;
};

// Errors the transport itself answers, numbered clear of every dialect's interpreter codes.
inline constexpr std::int32_t kErrorLineTooLong = 900;
inline constexpr std::int32_t kErrorBadCharacter = 901;

// Appends the wire form of `reply` to `out`. `;`, CR, LF and control bytes inside the text become
// a space so that the answer stays one frame; an error's text never starts with a digit.
void append_wire_reply(const Reply& reply, std::string& out);
std::string wire_reply(const Reply& reply);

// Reads one answer's wire form (without its `;`) back into a Reply: `?21 text` → {text, 21}.
// A `?` without a code gives error -1.
Reply parse_wire_reply(std::string_view answer);

}  // namespace uprog::transport
