// Reading one AG300 message (message.h).
#include "dialects/pup/message.h"

#include <cctype>
#include <charconv>

#include "dialects/pup/pup_lexer.h"

namespace uprog::pup {
namespace {

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}
  void blanks() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  bool at_end() {
    blanks();
    return pos_ >= text_.size();
  }
  bool take(char c) {
    blanks();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  std::string_view name() {
    blanks();
    const size_t start = pos_;
    if (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]))) {
      while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }
  std::string_view number_text() {
    blanks();
    const size_t start = pos_;
    if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) ++pos_;
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  bool peek_alpha() {
    blanks();
    return pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]));
  }

 private:
  std::string_view text_;
  size_t pos_ = 0;
};

// `AKey` or `AKey[n]`; false on a syntax error (code in `error`).
bool read_ref(Reader& r, ParamRef& out, int32_t* error) {
  const std::string_view key = r.name();
  if (key.empty()) return (*error = 2), false;
  out.key = std::string(key);
  if (r.take('[')) {
    const auto n = parse_number(r.number_text());
    if (!n || !r.take(']')) return (*error = 2), false;
    out.has_index = true;
    out.index = *n;
  }
  return true;
}

}  // namespace

std::optional<int32_t> parse_number(std::string_view text, bool allow_binary) {
  bool negative = false;
  std::string_view t = text;
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) {
    negative = t[0] == '-';
    t.remove_prefix(1);
  }
  int base = 10;
  if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X'))
    base = 16;
  else if (allow_binary && t.size() > 2 && t[0] == '0' && (t[1] == 'b' || t[1] == 'B'))
    base = 2;
  if (base != 10) {
    if (negative || text[0] == '+') return std::nullopt;  // 0x and 0b are unsigned bit patterns
    t.remove_prefix(2);
  }
  if (t.empty()) return std::nullopt;
  uint64_t v = 0;
  const auto [p, e] = std::from_chars(t.data(), t.data() + t.size(), v, base);
  if (e != std::errc() || p != t.data() + t.size()) return std::nullopt;
  if (base != 10) {
    if (v > 0xFFFFFFFFull) return std::nullopt;
    return static_cast<int32_t>(static_cast<uint32_t>(v));
  }
  if (negative ? v > 2147483648ull : v > 2147483647ull) return std::nullopt;
  return negative ? static_cast<int32_t>(-static_cast<int64_t>(v)) : static_cast<int32_t>(v);
}

std::optional<Message> parse_message(std::string_view text, int32_t* error) {
  int32_t scratch = 0;
  if (error == nullptr) error = &scratch;
  Reader r(text);
  Message m;
  if (!read_ref(r, m.target, error)) return std::nullopt;
  if (r.take('=')) {
    m.tail = Message::Tail::Assign;
    const auto v = parse_number(r.number_text());
    if (!v) return (*error = 2), std::nullopt;
    m.value = *v;
  } else if (r.take(',')) {
    m.tail = Message::Tail::Argument;
    if (r.peek_alpha()) {
      m.tail_is_name = true;
      if (!read_ref(r, m.name, error)) return std::nullopt;
    } else {
      const auto v = parse_number(r.number_text());
      if (!v) return (*error = 6), std::nullopt;
      m.value = *v;
    }
  }
  if (!r.at_end()) return (*error = 2), std::nullopt;
  return m;
}

}  // namespace uprog::pup
