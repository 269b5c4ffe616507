// format_message(): each conversion is parsed, rebuilt as a C format with only the flags that
// C defines for it, and handed to snprintf with the word converted to the type it expects.
#include "support/format_message.h"

#include <cstdio>
#include <vector>

namespace uprog {
namespace {

struct Conversion {
  size_t begin = 0;  // the '%'
  size_t end = 0;    // one past the conversion letter
  std::string flags;
  int width = -1;      // -1: none
  int precision = -1;  // -1: none
  char letter = 0;
};

bool is_flag(char c) { return c == '-' || c == '+' || c == ' ' || c == '#' || c == '0'; }
bool takes_word(char letter) { return letter != '%'; }
bool is_letter(char c) {
  switch (c) {
    case 'd':
    case 'i':
    case 'u':
    case 'x':
    case 'X':
    case 'c':
    case 's':
    case 'f':
    case 'e':
    case 'E':
    case 'g':
    case 'G':
    case '%':
      return true;
    default:
      return false;
  }
}

// A run of digits, capped; false when there is none.
bool read_number(std::string_view f, size_t& at, int& out) {
  if (at >= f.size() || f[at] < '0' || f[at] > '9') return false;
  long n = 0;
  while (at < f.size() && f[at] >= '0' && f[at] <= '9') {
    n = n * 10 + (f[at++] - '0');
    if (n > kMaxFormatWidth) n = kMaxFormatWidth;
  }
  out = static_cast<int>(n);
  return true;
}

// The conversion starting at f[at] == '%', or false when it is none (printed as it stands).
bool parse(std::string_view f, size_t at, Conversion& c) {
  c = Conversion{};
  c.begin = at++;
  if (at < f.size() && f[at] == '%') {
    c.letter = '%';
    c.end = at + 1;
    return true;
  }
  while (at < f.size() && is_flag(f[at])) c.flags += f[at++];
  read_number(f, at, c.width);
  if (at < f.size() && f[at] == '.') {
    ++at;
    if (!read_number(f, at, c.precision)) c.precision = 0;  // "%.f" is precision 0, as in C
  }
  if (at < f.size() && f[at] == 'l') ++at;
  if (at >= f.size() || !is_letter(f[at]) || f[at] == '%') return false;
  c.letter = f[at];
  c.end = at + 1;
  return true;
}

// The flags C defines for the letter, so that snprintf never sees an undefined combination.
std::string defined_flags(const Conversion& c) {
  std::string allowed;
  switch (c.letter) {
    case 'd':
    case 'i':
      allowed = "-+ 0";
      break;
    case 'u':
      allowed = "-0";
      break;
    case 'x':
    case 'X':
      allowed = "-#0";
      break;
    case 'c':
    case 's':
      allowed = "-";
      break;
    default:
      allowed = "-+ #0";
      break;  // the floats
  }
  std::string out;
  for (char f : c.flags)
    if (allowed.find(f) != std::string::npos && out.find(f) == std::string::npos) out += f;
  return out;
}

std::string c_format(const Conversion& c, char letter) {
  std::string spec = "%" + defined_flags(c);
  if (c.width >= 0) spec += std::to_string(c.width);
  if (c.precision >= 0 && c.letter != 'c') spec += "." + std::to_string(c.precision);
  return spec + letter;
}

template <typename T>
std::string print(const std::string& spec, T value) {
  const int n = std::snprintf(nullptr, 0, spec.c_str(), value);
  if (n <= 0) return {};
  std::vector<char> out(static_cast<size_t>(n) + 1);
  std::snprintf(out.data(), out.size(), spec.c_str(), value);
  return std::string(out.data(), static_cast<size_t>(n));
}

// The bytes of `count` words, low byte first, up to a NUL.
std::string bytes_of(const Value* words, size_t count) {
  std::string s;
  for (size_t i = 0; i < count; ++i)
    for (int k = 0; k < 4; ++k) {
      const auto byte = static_cast<char>((words[i].bits >> (8 * k)) & 0xFFu);
      if (byte == '\0') return s;
      s += byte;
    }
  return s;
}

std::string convert(const Conversion& c, const Value* words, size_t count) {
  const Value word = count > 0 ? words[0] : Value::of_bits(0);
  switch (c.letter) {
    case 'd':
    case 'i':
      return print(c_format(c, 'd'), static_cast<int>(word.i));
    case 'u':
    case 'x':
    case 'X':
      return print(c_format(c, c.letter), static_cast<unsigned>(word.bits));
    case 'c':
      return print(c_format(c, 'c'), static_cast<int>(word.bits & 0xFFu));
    case 's':
      return print(c_format(c, 's'), bytes_of(words, count).c_str());
    default:
      return print(c_format(c, c.letter), static_cast<double>(word.f));
  }
}

}  // namespace

std::string format_message(std::string_view format, const Value* args, size_t count) {
  std::vector<Conversion> conversions;
  for (size_t at = format.find('%'); at != std::string_view::npos;) {
    Conversion c;
    if (parse(format, at, c)) {
      conversions.push_back(c);
      at = format.find('%', c.end);
    } else {
      at = format.find('%', at + 1);
    }
  }
  std::string out;
  size_t printed = 0;  // of the format
  size_t next = 0;     // the next argument word
  for (size_t i = 0; i < conversions.size(); ++i) {
    const Conversion& c = conversions[i];
    out.append(format.substr(printed, c.begin - printed));
    printed = c.end;
    if (c.letter == '%') {
      out += '%';
      continue;
    }
    size_t taken = 1;
    if (c.letter == 's') {
      size_t later = 0;
      for (size_t k = i + 1; k < conversions.size(); ++k)
        later += takes_word(conversions[k].letter) ? 1 : 0;
      const size_t left = next < count ? count - next : 0;
      taken = left > later ? left - later : 0;
    }
    const size_t available = next < count ? count - next : 0;
    out += convert(c, args + (available > 0 ? next : 0), taken < available ? taken : available);
    next += taken;
  }
  out.append(format.substr(printed));
  return out;
}

}  // namespace uprog
