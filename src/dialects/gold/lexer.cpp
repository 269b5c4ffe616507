// The Gold lexer: a character-class table and one token per call, no allocation.
#include "dialects/gold/lexer.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace uprog::gold {

const char* tok_spelling(Tok t) {
  switch (t) {
    case Tok::Ident:
      return "name";
    case Tok::Int:
      return "integer";
    case Tok::Float:
      return "number";
    case Tok::Label:
      return "##label";
    case Tok::AutoLabel:
      return "#@label";
    case Tok::Newline:
      return "end of line";
    case Tok::Semicolon:
      return ";";
    case Tok::Comma:
      return ",";
    case Tok::Colon:
      return ":";
    case Tok::LParen:
      return "(";
    case Tok::RParen:
      return ")";
    case Tok::LBracket:
      return "[";
    case Tok::RBracket:
      return "]";
    case Tok::Plus:
      return "+";
    case Tok::Minus:
      return "-";
    case Tok::Star:
      return "*";
    case Tok::Slash:
      return "/";
    case Tok::Percent:
      return "%";
    case Tok::Tilde:
      return "~";
    case Tok::Bang:
      return "!";
    case Tok::Shl:
      return "<<";
    case Tok::Shr:
      return ">>";
    case Tok::Lt:
      return "<";
    case Tok::Le:
      return "<=";
    case Tok::Gt:
      return ">";
    case Tok::Ge:
      return ">=";
    case Tok::EqEq:
      return "==";
    case Tok::Ne:
      return "!=";
    case Tok::Amp:
      return "&";
    case Tok::Pipe:
      return "|";
    case Tok::AndAnd:
      return "&&";
    case Tok::OrOr:
      return "||";
    case Tok::Assign:
      return "=";
    case Tok::PlusPlus:
      return "++";
    case Tok::MinusMinus:
      return "--";
    case Tok::Unknown:
      return "character";
    case Tok::Eof:
      return "end of file";
  }
  return "?";
}

namespace {

// The manual (2.7.2, error 52) limits one clause, continuation lines included, to 512 characters.
constexpr size_t kMaxClause = 512;

// Character classes, one table lookup per character in the hot loops.
enum : uint8_t { kIdentStart = 1, kIdentChar = 2, kDigit = 4, kHex = 8, kBlank = 16 };

constexpr auto kClass = [] {
  struct Table {
    uint8_t c[256] = {};
  } t;
  for (int ch = 0; ch < 256; ++ch) {
    uint8_t k = 0;
    const bool letter = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || ch == '_';
    const bool digit = ch >= '0' && ch <= '9';
    if (letter) k |= kIdentStart | kIdentChar;
    if (digit) k |= kIdentChar | kDigit | kHex;
    if ((ch >= 'a' && ch <= 'f') || (ch >= 'A' && ch <= 'F')) k |= kHex;
    if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\f' || ch == '\v') k |= kBlank;
    t.c[ch] = k;
  }
  return t;
}();

inline bool is(char c, uint8_t k) { return (kClass.c[static_cast<unsigned char>(c)] & k) != 0; }
inline bool is_ident_start(char c) { return is(c, kIdentStart); }
inline bool is_digit(char c) { return is(c, kDigit); }

}  // namespace

Token Lexer::make(Tok k, size_t b, size_t n) {
  Token t;
  t.kind = k;
  t.offset = static_cast<uint32_t>(b);
  t.length = static_cast<uint32_t>(n);
  st_.last = k;
  return t;
}

// The end of a clause: checks its length and makes a Newline token unless one was just made.
bool Lexer::newline(size_t at, Token& out) {
  if (at - st_.clause_start > kMaxClause) r_.lex_error(Error::ClauseIsTooLong, st_.clause_start);
  st_.clause_start = static_cast<uint32_t>(at + 1);
  // A full reporter keeps no more errors: the lines after this one are not read (a binary file).
  if (r_.full()) st_.pos = static_cast<uint32_t>(s_.size());
  if (st_.last == Tok::Newline) return false;
  out = make(Tok::Newline, at, 0);
  return true;
}

// Spaces, tabs, carriage returns and comments; a block comment that spans lines ends the line
// (true, with the Newline token in `out`).
bool Lexer::skip_blank(Token& out) {
  const char* const begin = s_.data();
  const char* const end = begin + s_.size();
  const char* p = begin + st_.pos;
  while (p < end) {
    const char c = *p;
    if (is(c, kBlank)) {
      ++p;
    } else if ((c == '/' || c == '*') && p + 1 < end && p[1] == c) {  // "//", "**"
      const void* e = std::memchr(p, '\n', static_cast<size_t>(end - p));
      p = e == nullptr ? end : static_cast<const char*>(e);
    } else if (c == '/' && p + 1 < end && p[1] == '*') {
      const size_t b = static_cast<size_t>(p - begin);
      const size_t e = s_.find("*/", b + 2);
      const size_t stop = e == std::string_view::npos ? s_.size() : e + 2;
      const bool spans = std::memchr(p, '\n', stop - b) != nullptr;
      p = begin + stop;
      st_.pos = static_cast<uint32_t>(stop);
      if (e == std::string_view::npos) {
        r_.lex_error(Error::BlockCommentNotFinished, static_cast<uint32_t>(b));
        return false;
      }
      if (spans && newline(b, out)) return true;
    } else {
      break;
    }
  }
  st_.pos = static_cast<uint32_t>(p - begin);
  return false;
}

Token Lexer::next() {
  Token out;
  while (true) {
    if (skip_blank(out)) return out;
    size_t i = st_.pos;
    const size_t n = s_.size();
    if (i >= n) {
      if (!st_.at_end) {
        st_.at_end = true;
        if (newline(n, out)) return out;
      }
      return make(Tok::Eof, n, 0);
    }
    const char c = s_[i];
    if (is_ident_start(c)) {
      const size_t b = i;
      const char* const text = s_.data();
      while (i < n && is(text[i], kIdentChar)) ++i;
      st_.pos = static_cast<uint32_t>(i);
      out = make(Tok::Ident, b, i - b);
      out.kw = keyword_of(s_.substr(b, i - b));
      return out;
    }
    if (c == '\n') {
      st_.pos = static_cast<uint32_t>(i + 1);
      if (newline(i, out)) return out;
      continue;
    }
    if (is_digit(c) || (c == '.' && i + 1 < n && is_digit(s_[i + 1]))) return number();
    if (c == '.' && s_.substr(i, 3) == "...") {
      continuation();
      continue;
    }
    if (c == '#' && i + 1 < n &&
        (s_[i + 1] == '#' || s_[i + 1] == '@' || is_ident_start(s_[i + 1]))) {
      // "#start" is read as "##start": the manual's own example (2.6) writes it so.
      const size_t b = i;
      const Tok kind = s_[i + 1] == '@' ? Tok::AutoLabel : Tok::Label;
      const uint8_t skip = is_ident_start(s_[i + 1]) ? 1 : 2;
      i += skip;
      while (i < n && is(s_[i], kIdentChar)) ++i;
      st_.pos = static_cast<uint32_t>(i);
      out = make(kind, b, i - b);
      out.name_skip = skip;
      return out;
    }
    return punct();
  }
}

// "..." joins the next line to this one; what follows it on its own line is a comment.
void Lexer::continuation() {
  size_t i = st_.pos;
  const size_t b = i;
  const size_t n = s_.size();
  while (i < n && s_[i] != '\n') ++i;
  if (i < n) ++i;
  st_.pos = static_cast<uint32_t>(i);
  // The manual's error 64: an ellipsis must be followed by another line with something on it.
  size_t k = i;
  while (k < n && (s_[k] == ' ' || s_[k] == '\t' || s_[k] == '\r' || s_[k] == '\n')) ++k;
  if (k >= n) r_.lex_error(Error::ExpressionNotFinished, static_cast<uint32_t>(b));
}

constexpr size_t kMaxFractionDigits = 12;

// True when a run of decimal digits, read as an integer, is above 2147483647.
static bool digits_exceed_long(std::string_view digits) {
  while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
  return digits.size() > 10 || (digits.size() == 10 && digits > "2147483647");
}

Token Lexer::number() {
  size_t i = st_.pos;
  const size_t b = i;
  const size_t n = s_.size();
  if (s_[i] == '0' && i + 1 < n && (s_[i + 1] == 'x' || s_[i + 1] == 'X')) {
    i += 2;
    const size_t digits = i;
    uint64_t v = 0;
    while (i < n && is(s_[i], kHex)) {
      const char c = s_[i];
      const uint64_t d = is_digit(c) ? static_cast<uint64_t>(c - '0')
                                     : static_cast<uint64_t>((c | 0x20) - 'a' + 10);
      v = v * 16 + d;
      if (v > 0xFFFFFFFFull) v = 0x100000000ull;
      ++i;
    }
    st_.pos = static_cast<uint32_t>(i);
    Token t = make(Tok::Int, b, i - b);
    if (i == digits || v > 0xFFFFFFFFull) r_.lex_error(Error::BadFormat, static_cast<uint32_t>(b));
    t.int_value = static_cast<int32_t>(static_cast<uint32_t>(v));
    return t;
  }
  bool is_float = false;
  while (i < n && is_digit(s_[i])) ++i;
  // "1:" and "a.b" are not floats; a dot followed by a second dot starts "...".
  if (i < n && s_[i] == '.' && s_.substr(i, 3) != "...") {
    is_float = true;
    const size_t point = i++;
    while (i < n && is_digit(s_[i])) ++i;
    // Manual 1.3.2, "Number Overflow": the integer left of the point must fit a long; right of it,
    // 13 digits are an error and 12 are not (1.7 computes sin(0.523598775598)):
    // docs/dialects/gold.md.
    if (digits_exceed_long(s_.substr(b, point - b)) || i - point - 1 > kMaxFractionDigits) {
      r_.lex_error(Error::BadFormat, static_cast<uint32_t>(b));
    }
  }
  if (i < n && (s_[i] == 'e' || s_[i] == 'E')) {
    size_t k = i + 1;
    if (k < n && (s_[k] == '+' || s_[k] == '-')) ++k;
    if (k < n && is_digit(s_[k])) {
      is_float = true;
      i = k;
      while (i < n && is_digit(s_[i])) ++i;
    }
  }
  st_.pos = static_cast<uint32_t>(i);
  if (!is_float) {
    // Most integers fit: read them here, without a string and strtol.
    uint64_t v = 0;
    size_t k = b;
    while (k < i && v <= 2147483647u) v = v * 10 + static_cast<uint64_t>(s_[k++] - '0');
    if (v <= 2147483647u) {
      Token t = make(Tok::Int, b, i - b);
      t.int_value = static_cast<int32_t>(v);
      return t;
    }
  }
  const std::string spelling(s_.substr(b, i - b));
  if (!is_float) {
    const double d = std::strtod(spelling.c_str(), nullptr);
    // Manual 1.3: an integer beyond the int range is taken as a float.
    if (d > 2147483647.0) {
      Token t = make(Tok::Float, b, i - b);
      t.float_value = static_cast<float>(d);
      return t;
    }
    Token t = make(Tok::Int, b, i - b);
    t.int_value = static_cast<int32_t>(std::strtol(spelling.c_str(), nullptr, 10));
    return t;
  }
  Token t = make(Tok::Float, b, i - b);
  // from_chars rounds as strtod does; out of range it leaves `d` alone, so strtod decides.
  double d = 0.0;
  const auto [end, ec] = std::from_chars(spelling.data(), spelling.data() + spelling.size(), d);
  if (ec != std::errc{} || end != spelling.data() + spelling.size())
    d = std::strtod(spelling.c_str(), nullptr);
  // Manual 1.3: floats live in -1e37 < N < 1e37; anything else is an error.
  if (!(std::fabs(d) < 1e37)) r_.lex_error(Error::BadFormat, static_cast<uint32_t>(b));
  t.float_value = std::fabs(d) < 1e37 ? static_cast<float>(d) : 0.0f;
  return t;
}

Token Lexer::punct() {
  const size_t i = st_.pos;
  const char c = s_[i];
  const char d = i + 1 < s_.size() ? s_[i + 1] : '\0';
  Tok k = Tok::Unknown;
  size_t n = 2;
  switch (c) {
    case '<':
      k = d == '<' ? Tok::Shl : d == '=' ? Tok::Le : Tok::Lt;
      break;
    case '>':
      k = d == '>' ? Tok::Shr : d == '=' ? Tok::Ge : Tok::Gt;
      break;
    case '=':
      k = d == '=' ? Tok::EqEq : Tok::Assign;
      break;
    case '!':
      k = d == '=' ? Tok::Ne : Tok::Bang;
      break;
    case '&':
      k = d == '&' ? Tok::AndAnd : Tok::Amp;
      break;
    case '|':
      k = d == '|' ? Tok::OrOr : Tok::Pipe;
      break;
    case '+':
      k = d == '+' ? Tok::PlusPlus : Tok::Plus;
      break;
    case '-':
      k = d == '-' ? Tok::MinusMinus : Tok::Minus;
      break;
    default:
      break;
  }
  switch (k) {
    case Tok::Lt:
    case Tok::Gt:
    case Tok::Assign:
    case Tok::Bang:
    case Tok::Amp:
    case Tok::Pipe:
    case Tok::Plus:
    case Tok::Minus:
      n = 1;
      break;
    case Tok::Unknown: {
      n = 1;
      switch (c) {
        case ';':
          k = Tok::Semicolon;
          break;
        case ',':
          k = Tok::Comma;
          break;
        case ':':
          k = Tok::Colon;
          break;
        case '(':
          k = Tok::LParen;
          break;
        case ')':
          k = Tok::RParen;
          break;
        case '[':
          k = Tok::LBracket;
          break;
        case ']':
          k = Tok::RBracket;
          break;
        case '*':
          k = Tok::Star;
          break;
        case '/':
          k = Tok::Slash;
          break;
        case '%':
          k = Tok::Percent;
          break;
        case '~':
          k = Tok::Tilde;
          break;
        default: {
          // One token for a whole UTF-8 sequence, so that columns stay on the character.
          if (static_cast<unsigned char>(c) >= 0xC0) {
            while (i + n < s_.size() && (static_cast<unsigned char>(s_[i + n]) & 0xC0) == 0x80) ++n;
          }
        }
      }
      break;
    }
    default:
      break;
  }
  st_.pos = static_cast<uint32_t>(i + n);
  return make(k, i, n);
}

}  // namespace uprog::gold
