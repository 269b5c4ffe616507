// How the debugger shows a VM word of a known type and reads one a user typed: dialect-neutral,
// the same for every dialect's variables (a dialect's own formatting is its evaluate()).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "support/value.h"

namespace uprog::debug {

// "42", "2.5", "3.0": a float always shows a point or an exponent, so its type is visible.
std::string show_value(Value v, ValueType type);
// nullopt when the text is not a number of that type ("12", "-3", "0x1F"; "2.5", "1e3").
std::optional<Value> parse_value(std::string_view text, ValueType type);

}  // namespace uprog::debug
