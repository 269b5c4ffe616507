// Checked field access (fields.h).
#include "jsonrpc/fields.h"

#include <string>

namespace uprog::jsonrpc {
namespace {

[[noreturn]] void wrong(std::string_view what, std::string_view expected) {
  throw FieldError(std::string(what) + ": expected " + std::string(expected));
}

const json* checked_find(const json& object, std::string_view key) {
  if (!object.is_object())
    throw FieldError("expected an object holding \"" + std::string(key) + "\"");
  return find(object, key);
}

}  // namespace

const json* find(const json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return nullptr;
  return &*it;
}

std::optional<std::string> peek_string(const json& object, std::string_view key) {
  const json* v = find(object, key);
  if (v == nullptr || !v->is_string()) return std::nullopt;
  return v->get<std::string>();
}

std::string as_string(const json& value, std::string_view what) {
  if (!value.is_string()) wrong(what, "a string");
  return value.get<std::string>();
}

int64_t as_integer(const json& value, std::string_view what, int64_t min, int64_t max) {
  const std::string range = "an integer from " + std::to_string(min) + " to " + std::to_string(max);
  if (value.is_number_unsigned()) {
    // Above INT64_MAX it is out of every range an int64_t can name.
    const uint64_t u = value.get<uint64_t>();
    if (u > static_cast<uint64_t>(max)) wrong(what, range);
    return static_cast<int64_t>(u);
  }
  if (!value.is_number_integer()) wrong(what, "an integer");
  const int64_t i = value.get<int64_t>();
  if (i < min || i > max) wrong(what, range);
  return i;
}

void require_object(const json& value, std::string_view what) {
  if (!value.is_object()) wrong(what, "an object");
}

std::string string_or(const json& object, std::string_view key, std::string fallback) {
  const json* v = checked_find(object, key);
  return v == nullptr ? fallback : as_string(*v, key);
}

std::string required_string(const json& object, std::string_view key) {
  const json* v = checked_find(object, key);
  if (v == nullptr) wrong(key, "a string (it is missing)");
  return as_string(*v, key);
}

bool bool_or(const json& object, std::string_view key, bool fallback) {
  const json* v = checked_find(object, key);
  if (v == nullptr) return fallback;
  if (!v->is_boolean()) wrong(key, "true or false");
  return v->get<bool>();
}

double number_or(const json& object, std::string_view key, double fallback) {
  const json* v = checked_find(object, key);
  if (v == nullptr) return fallback;
  if (!v->is_number()) wrong(key, "a number");
  return v->get<double>();
}

int64_t integer_or(const json& object, std::string_view key, int64_t fallback, int64_t min,
                   int64_t max) {
  const json* v = checked_find(object, key);
  return v == nullptr ? fallback : as_integer(*v, key, min, max);
}

int64_t required_integer(const json& object, std::string_view key, int64_t min, int64_t max) {
  const json* v = checked_find(object, key);
  if (v == nullptr) wrong(key, "an integer (it is missing)");
  return as_integer(*v, key, min, max);
}

const json& object_or_empty(const json& object, std::string_view key) {
  static const json kEmpty = json::object();
  const json* v = checked_find(object, key);
  if (v == nullptr) return kEmpty;
  require_object(*v, key);
  return *v;
}

const json& required_object(const json& object, std::string_view key) {
  const json* v = checked_find(object, key);
  if (v == nullptr) wrong(key, "an object (it is missing)");
  require_object(*v, key);
  return *v;
}

const json& array_or_empty(const json& object, std::string_view key) {
  static const json kEmpty = json::array();
  const json* v = checked_find(object, key);
  if (v == nullptr) return kEmpty;
  if (!v->is_array()) wrong(key, "an array");
  return *v;
}

std::vector<std::string> strings_or_empty(const json& object, std::string_view key) {
  std::vector<std::string> out;
  for (const json& v : array_or_empty(object, key)) out.push_back(as_string(v, key));
  return out;
}

std::vector<double> numbers_or_empty(const json& object, std::string_view key) {
  std::vector<double> out;
  for (const json& v : array_or_empty(object, key)) {
    if (!v.is_number()) wrong(key, "an array of numbers");
    out.push_back(v.get<double>());
  }
  return out;
}

bool parse_message(std::string_view text, json& out, std::string& why) {
  // The depth, counted outside strings before anything is built.
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxNesting) {
        why = "a message nested deeper than " + std::to_string(kMaxNesting) + " levels";
        return false;
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  out = json::parse(text, nullptr, false);
  if (out.is_discarded()) {
    why = "not a JSON text";
    return false;
  }
  return true;
}

std::string to_text(const json& message) {
  return message.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace uprog::jsonrpc
