// One AG300 message as the wire and a CUP line write it: `AKey`, `AKey[i]`, then `=value` or
// `,argument`; an argument is a number or a parameter's name (`APushParam,AGenData[200]`).
// The command line, the CUP loader and the PUP compiler's copies all read it here.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace uprog::pup {

struct ParamRef {
  std::string key;  // as written
  bool has_index = false;
  int32_t index = 0;
};

struct Message {
  ParamRef target;  // the keyword and its index
  enum class Tail : uint8_t { None, Assign, Argument } tail = Tail::None;
  bool tail_is_name = false;  // `,AKey[i]` rather than `,number`
  int32_t value = 0;          // the number after `=` or `,`
  ParamRef name;              // the name after `,` when tail_is_name
};

// A decimal or 0x number (with a sign for decimal) filling `text`; 0b too where PUP allows it.
std::optional<int32_t> parse_number(std::string_view text, bool allow_binary = false);

// Blanks are skipped between tokens (the wire's rule); a CUP line has none to skip. nullopt
// with `error` the controller's code (2 syntax, 3 index missing..., 6 argument format).
std::optional<Message> parse_message(std::string_view text, int32_t* error);

}  // namespace uprog::pup
