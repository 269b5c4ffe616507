// The Gold lexer.
#include "dialects/gold/lexer.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace uprog::gold {

const char* tok_spelling(Tok t) {
  switch (t) {
    case Tok::Ident: return "name";
    case Tok::Int: return "integer";
    case Tok::Float: return "number";
    case Tok::Label: return "##label";
    case Tok::AutoLabel: return "#@label";
    case Tok::Newline: return "end of line";
    case Tok::Semicolon: return ";";
    case Tok::Comma: return ",";
    case Tok::Colon: return ":";
    case Tok::LParen: return "(";
    case Tok::RParen: return ")";
    case Tok::LBracket: return "[";
    case Tok::RBracket: return "]";
    case Tok::Plus: return "+";
    case Tok::Minus: return "-";
    case Tok::Star: return "*";
    case Tok::Slash: return "/";
    case Tok::Percent: return "%";
    case Tok::Tilde: return "~";
    case Tok::Bang: return "!";
    case Tok::Shl: return "<<";
    case Tok::Shr: return ">>";
    case Tok::Lt: return "<";
    case Tok::Le: return "<=";
    case Tok::Gt: return ">";
    case Tok::Ge: return ">=";
    case Tok::EqEq: return "==";
    case Tok::Ne: return "!=";
    case Tok::Amp: return "&";
    case Tok::Pipe: return "|";
    case Tok::AndAnd: return "&&";
    case Tok::OrOr: return "||";
    case Tok::Assign: return "=";
    case Tok::PlusPlus: return "++";
    case Tok::MinusMinus: return "--";
    case Tok::Unknown: return "character";
    case Tok::Eof: return "end of file";
  }
  return "?";
}

namespace {

// The manual (2.7.2, error 52) limits one clause, continuation lines included, to 512 characters.
constexpr size_t kMaxClause = 512;

bool is_ident_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

class Lexer {
 public:
  Lexer(const std::string& text, Reporter& reporter) : s_(text), r_(reporter) {}

  std::vector<Token> run() {
    out_.reserve(s_.size() / 3 + 4);
    while (true) {
      skip_blank();
      if (i_ >= s_.size()) break;
      const char c = s_[i_];
      if (c == '\n') {
        newline(i_);
        ++i_;
        continue;
      }
      if (c == '.' && starts("...")) {
        continuation();
        continue;
      }
      if (is_digit(c) || (c == '.' && i_ + 1 < s_.size() && is_digit(s_[i_ + 1]))) {
        number();
        continue;
      }
      if (is_ident_start(c)) {
        const size_t b = i_;
        while (i_ < s_.size() && is_ident_char(s_[i_])) ++i_;
        push(Tok::Ident, b, i_ - b);
        out_.back().kw = keyword_of(out_.back().text);
        continue;
      }
      if (c == '#' && i_ + 1 < s_.size() &&
          (s_[i_ + 1] == '#' || s_[i_ + 1] == '@' || is_ident_start(s_[i_ + 1]))) {
        // "#start" is read as "##start": the manual's own example (2.6) writes it so.
        const size_t b = i_;
        const Tok kind = s_[i_ + 1] == '@' ? Tok::AutoLabel : Tok::Label;
        i_ += is_ident_start(s_[i_ + 1]) ? 1 : 2;
        const size_t name = i_;
        while (i_ < s_.size() && is_ident_char(s_[i_])) ++i_;
        Token t = make(kind, b, i_ - b);
        t.text = std::string_view(s_).substr(name, i_ - name);
        out_.push_back(t);
        continue;
      }
      punct();
    }
    newline(s_.size());
    out_.push_back(make(Tok::Eof, s_.size(), 0));
    return std::move(out_);
  }

 private:
  bool starts(const char* p) const { return s_.compare(i_, std::char_traits<char>::length(p), p) == 0; }

  Token make(Tok k, size_t b, size_t n) const {
    Token t;
    t.kind = k;
    t.offset = static_cast<uint32_t>(b);
    t.text = std::string_view(s_).substr(b, n);
    return t;
  }
  void push(Tok k, size_t b, size_t n) { out_.push_back(make(k, b, n)); }

  void newline(size_t at) {
    if (at - clause_start_ > kMaxClause && !clause_reported_) r_.error(Error::ClauseIsTooLong, static_cast<uint32_t>(clause_start_));
    clause_start_ = at + 1;
    clause_reported_ = false;
    if (!out_.empty() && out_.back().kind != Tok::Newline) push(Tok::Newline, at, 0);
  }

  // Spaces, tabs, carriage returns and comments; a block comment that spans lines ends the line.
  void skip_blank() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i_;
      } else if ((c == '/' || c == '*') && i_ + 1 < s_.size() && s_[i_ + 1] == c) {  // "//", "**"
        const size_t e = s_.find('\n', i_);
        i_ = e == std::string::npos ? s_.size() : e;
      } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
        const size_t b = i_;
        const size_t e = s_.find("*/", i_ + 2);
        const size_t stop = e == std::string::npos ? s_.size() : e + 2;
        bool spans = false;
        for (size_t k = b; k < stop; ++k) spans = spans || s_[k] == '\n';
        i_ = stop;
        if (e == std::string::npos) {
          r_.error(Error::BlockCommentNotFinished, static_cast<uint32_t>(b));
          return;
        }
        if (spans) newline(b);
      } else {
        return;
      }
    }
  }

  // "..." joins the next line to this one; what follows it on its own line is a comment.
  void continuation() {
    const size_t b = i_;
    while (i_ < s_.size() && s_[i_] != '\n') ++i_;
    if (i_ < s_.size()) ++i_;
    // The manual's error 64: an ellipsis must be followed by another line with something on it.
    size_t k = i_;
    while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t' || s_[k] == '\r' || s_[k] == '\n')) ++k;
    if (k >= s_.size()) r_.error(Error::ExpressionNotFinished, static_cast<uint32_t>(b));
  }

  void number() {
    const size_t b = i_;
    if (s_[i_] == '0' && i_ + 1 < s_.size() && (s_[i_ + 1] == 'x' || s_[i_ + 1] == 'X')) {
      i_ += 2;
      const size_t digits = i_;
      uint64_t v = 0;
      while (i_ < s_.size() && is_hex(s_[i_])) {
        const char c = s_[i_];
        const uint64_t d = is_digit(c) ? static_cast<uint64_t>(c - '0')
                                       : static_cast<uint64_t>((c | 0x20) - 'a' + 10);
        v = v * 16 + d;
        if (v > 0xFFFFFFFFull) v = 0x100000000ull;
        ++i_;
      }
      Token t = make(Tok::Int, b, i_ - b);
      if (i_ == digits || v > 0xFFFFFFFFull) r_.error(Error::BadFormat, static_cast<uint32_t>(b));
      t.int_value = static_cast<int32_t>(static_cast<uint32_t>(v));
      out_.push_back(t);
      return;
    }
    bool is_float = false;
    while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    // "1:" and "a.b" are not floats; a dot followed by a second dot starts "...".
    if (i_ < s_.size() && s_[i_] == '.' && !starts("...")) {
      is_float = true;
      ++i_;
      while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      size_t k = i_ + 1;
      if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
      if (k < s_.size() && is_digit(s_[k])) {
        is_float = true;
        i_ = k;
        while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
      }
    }
    if (!is_float) {
      // Most integers fit: read them here, without a string and strtol.
      uint64_t v = 0;
      size_t k = b;
      while (k < i_ && v <= 2147483647u) v = v * 10 + static_cast<uint64_t>(s_[k++] - '0');
      if (v <= 2147483647u) {
        Token t = make(Tok::Int, b, i_ - b);
        t.int_value = static_cast<int32_t>(v);
        out_.push_back(t);
        return;
      }
    }
    const std::string spelling = s_.substr(b, i_ - b);
    if (!is_float) {
      const double d = std::strtod(spelling.c_str(), nullptr);
      // Manual 1.3: an integer beyond the int range is taken as a float.
      if (d > 2147483647.0) {
        Token t = make(Tok::Float, b, i_ - b);
        t.float_value = static_cast<float>(d);
        out_.push_back(t);
        return;
      }
      Token t = make(Tok::Int, b, i_ - b);
      t.int_value = static_cast<int32_t>(std::strtol(spelling.c_str(), nullptr, 10));
      out_.push_back(t);
      return;
    }
    Token t = make(Tok::Float, b, i_ - b);
    // from_chars rounds as strtod does; out of range it leaves `d` alone, so strtod decides.
    double d = 0.0;
    const auto [end, ec] = std::from_chars(spelling.data(), spelling.data() + spelling.size(), d);
    if (ec != std::errc{} || end != spelling.data() + spelling.size()) d = std::strtod(spelling.c_str(), nullptr);
    // Manual 1.3: floats live in -1e37 < N < 1e37; anything else is an error.
    if (!(std::fabs(d) < 1e37)) r_.error(Error::BadFormat, static_cast<uint32_t>(b));
    t.float_value = std::fabs(d) < 1e37 ? static_cast<float>(d) : 0.0f;
    out_.push_back(t);
  }

  void punct() {
    const size_t b = i_;
    auto two = [&](char a, char c) { return s_[i_] == a && i_ + 1 < s_.size() && s_[i_ + 1] == c; };
    Tok k;
    size_t n = 2;
    if (two('<', '<')) k = Tok::Shl;
    else if (two('>', '>')) k = Tok::Shr;
    else if (two('<', '=')) k = Tok::Le;
    else if (two('>', '=')) k = Tok::Ge;
    else if (two('=', '=')) k = Tok::EqEq;
    else if (two('!', '=')) k = Tok::Ne;
    else if (two('&', '&')) k = Tok::AndAnd;
    else if (two('|', '|')) k = Tok::OrOr;
    else if (two('+', '+')) k = Tok::PlusPlus;
    else if (two('-', '-')) k = Tok::MinusMinus;
    else {
      n = 1;
      switch (s_[i_]) {
        case ';': k = Tok::Semicolon; break;
        case ',': k = Tok::Comma; break;
        case ':': k = Tok::Colon; break;
        case '(': k = Tok::LParen; break;
        case ')': k = Tok::RParen; break;
        case '[': k = Tok::LBracket; break;
        case ']': k = Tok::RBracket; break;
        case '+': k = Tok::Plus; break;
        case '-': k = Tok::Minus; break;
        case '*': k = Tok::Star; break;
        case '/': k = Tok::Slash; break;
        case '%': k = Tok::Percent; break;
        case '~': k = Tok::Tilde; break;
        case '!': k = Tok::Bang; break;
        case '<': k = Tok::Lt; break;
        case '>': k = Tok::Gt; break;
        case '&': k = Tok::Amp; break;
        case '|': k = Tok::Pipe; break;
        case '=': k = Tok::Assign; break;
        default: {
          // One token for a whole UTF-8 sequence, so that columns stay on the character.
          k = Tok::Unknown;
          const auto u = static_cast<unsigned char>(s_[i_]);
          if (u >= 0xC0) {
            while (i_ + n < s_.size() && (static_cast<unsigned char>(s_[i_ + n]) & 0xC0) == 0x80) ++n;
          }
        }
      }
    }
    i_ += n;
    push(k, b, n);
  }

  const std::string& s_;
  Reporter& r_;
  size_t i_ = 0;
  size_t clause_start_ = 0;
  bool clause_reported_ = false;
  std::vector<Token> out_;
};

}  // namespace

std::vector<Token> lex(const std::string& text, Reporter& reporter) {
  return Lexer(text, reporter).run();
}

}  // namespace uprog::gold
