// Writing and reading the `TEXT;` / `?CODE TEXT;` wire form (semicolon_wire.h).
#include "dialect/semicolon_wire.h"

#include <charconv>

namespace uprog::dialect {
namespace {

void append_clean(std::string_view text, std::string& out) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    out.push_back(c == ';' || byte < 0x20 || byte == 0x7f ? ' ' : c);
  }
}

}  // namespace

void append_semicolon_answer(const Answer& answer, std::string& out) {
  if (answer.error != 0) {
    out.push_back('?');
    out += std::to_string(answer.error);
    if (!answer.text.empty()) out.push_back(' ');
  } else if (!answer.text.empty() && answer.text.front() == '?') {
    out.push_back(' ');  // a value never reads as an error
  }
  append_clean(answer.text, out);
  out.push_back(';');
}

void SemicolonWire::write_answer(const Answer& answer, std::string& out) const {
  append_semicolon_answer(answer, out);
}

void SemicolonWire::write_output(std::string_view text, std::string& out) const {
  if (!out.empty() && out.back() != '\n') out += "\r\n";
  append_clean(text, out);
  out += "\r\n";
}

void SemicolonWire::write_lost_output(uint64_t count, std::string& out) const {
  if (lost_prefix_.empty()) return;
  write_output(lost_prefix_ + std::to_string(count), out);
}

Answer parse_semicolon_answer(std::string_view answer) {
  if (answer.empty() || answer.front() != '?') return {std::string(answer), 0};
  answer.remove_prefix(1);
  std::int32_t code = -1;
  const auto [end, ec] = std::from_chars(answer.data(), answer.data() + answer.size(), code);
  if (ec != std::errc{}) code = -1;
  answer.remove_prefix(static_cast<std::size_t>(end - answer.data()));
  if (!answer.empty() && answer.front() == ' ') answer.remove_prefix(1);
  return {std::string(answer), code};
}

}  // namespace uprog::dialect
