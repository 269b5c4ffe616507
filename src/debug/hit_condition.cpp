// Parsing and testing hit count conditions (hit_condition.h).
#include "debug/hit_condition.h"

#include <charconv>

namespace uprog::debug {

bool HitCondition::met(uint64_t hits) const {
  switch (kind) {
    case Kind::Always:
      return true;
    case Kind::Equal:
      return hits == n;
    case Kind::Multiple:
      return hits % n == 0;
    case Kind::AtLeast:
      return hits >= n;
  }
  return true;
}

std::optional<HitCondition> parse_hit_condition(std::string_view text, std::string* error) {
  auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  text = trim(text);
  HitCondition c;
  if (text.empty()) return c;
  c.kind = HitCondition::Kind::Equal;
  if (text.starts_with("==")) {
    text.remove_prefix(2);
  } else if (text.starts_with(">=")) {
    c.kind = HitCondition::Kind::AtLeast;
    text.remove_prefix(2);
  } else if (text.starts_with("%")) {
    c.kind = HitCondition::Kind::Multiple;
    text.remove_prefix(1);
  }
  text = trim(text);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), c.n);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || c.n == 0) {
    if (error) *error = "a hit count is N, ==N, %N or >=N with N a positive whole number";
    return std::nullopt;
  }
  return c;
}

}  // namespace uprog::debug
