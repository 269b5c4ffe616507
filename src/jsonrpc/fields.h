// Typed access to the fields of a protocol message: each field's type (and an integer's range) is
// checked before it is read, so a hostile message gets an answer that names the field instead of
// a library exception or a number cast out of range. Absent and null fields take the fallback.
#pragma once
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace uprog::jsonrpc {

using json = nlohmann::json;

// A field of the wrong type or out of its range; what() names it ("line: expected an integer").
class FieldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The member `key` of `object`; nullptr when `object` is not an object, or the member is absent
// or null. Never throws.
const json* find(const json& object, std::string_view key);
// The member when it is a string; nullopt otherwise. Never throws.
std::optional<std::string> peek_string(const json& object, std::string_view key);

// The checked readers: FieldError when `object` is not an object or the member has another type.
std::string string_or(const json& object, std::string_view key, std::string fallback);
std::string required_string(const json& object, std::string_view key);
bool bool_or(const json& object, std::string_view key, bool fallback);
double number_or(const json& object, std::string_view key, double fallback);
int64_t integer_or(const json& object, std::string_view key, int64_t fallback,
                   int64_t min = std::numeric_limits<int64_t>::min(),
                   int64_t max = std::numeric_limits<int64_t>::max());
int64_t required_integer(const json& object, std::string_view key,
                         int64_t min = std::numeric_limits<int64_t>::min(),
                         int64_t max = std::numeric_limits<int64_t>::max());
// An object member; an empty object when absent (`arguments`, `params`).
const json& object_or_empty(const json& object, std::string_view key);
const json& required_object(const json& object, std::string_view key);
// An array member; an empty array when absent.
const json& array_or_empty(const json& object, std::string_view key);
std::vector<std::string> strings_or_empty(const json& object, std::string_view key);
std::vector<double> numbers_or_empty(const json& object, std::string_view key);

// One value (an array's element), `what` naming it in the error.
std::string as_string(const json& value, std::string_view what);
int64_t as_integer(const json& value, std::string_view what,
                   int64_t min = std::numeric_limits<int64_t>::min(),
                   int64_t max = std::numeric_limits<int64_t>::max());
void require_object(const json& value, std::string_view what);

// A message's text parsed: false with `why` set when it is not JSON, or nests deeper than
// kMaxNesting arrays and objects (no protocol message does; a deeper one would cost a copy or a
// dump its depth in stack frames).
constexpr int kMaxNesting = 64;
bool parse_message(std::string_view text, json& out, std::string& why);

// The text of a message to send: bytes that are not UTF-8 (a program's output, a request's own
// text) are replaced rather than thrown on.
std::string to_text(const json& message);

}  // namespace uprog::jsonrpc
