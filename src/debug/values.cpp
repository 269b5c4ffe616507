// Showing and parsing variable values for the debugger (values.h).
#include "debug/values.h"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace uprog::debug {

std::string show_value(Value v, ValueType type) {
  if (type == ValueType::Int) return std::to_string(v.i);
  std::string s = fmt::format("{}", v.f);
  if (std::isfinite(v.f) && s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::optional<Value> parse_value(std::string_view text, ValueType type) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (text.empty()) return std::nullopt;
  if (type == ValueType::Int) {
    int32_t n = 0;
    const bool negative = text.front() == '-';
    std::string_view digits = negative ? text.substr(1) : text;
    int base = 10;
    if (digits.starts_with("0x") || digits.starts_with("0X")) {
      digits.remove_prefix(2);
      base = 16;
    }
    int64_t magnitude = 0;
    const auto [end, ec] =
        std::from_chars(digits.data(), digits.data() + digits.size(), magnitude, base);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size())
      return std::nullopt;
    const int64_t value = negative ? -magnitude : magnitude;
    if (value < INT32_MIN || value > INT32_MAX) return std::nullopt;
    n = static_cast<int32_t>(value);
    return Value::of_int(n);
  }
  const std::string copy(text);
  char* end = nullptr;
  const double d = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size()) return std::nullopt;
  return Value::of_float(static_cast<float>(d));
}

}  // namespace uprog::debug
