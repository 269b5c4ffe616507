// A breakpoint's hit count condition, as the Debug Adapter Protocol's hitCondition writes it:
// "N" or "==N" stops at the N-th hit, "%N" at every N-th, ">=N" from the N-th on.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace uprog::debug {

struct HitCondition {
  enum class Kind : uint8_t { Always, Equal, Multiple, AtLeast };
  Kind kind = Kind::Always;
  uint64_t n = 0;
  bool met(uint64_t hits) const;
};

// nullopt with `error` set when the text is none of the forms above ("" is Always).
std::optional<HitCondition> parse_hit_condition(std::string_view text, std::string* error);

}  // namespace uprog::debug
