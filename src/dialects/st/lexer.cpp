// The ST lexer (lexer.h).
#include "dialects/st/lexer.h"

#include <cctype>

namespace uprog::st {
namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_char(char c) { return is_letter(c) || is_digit(c) || c == '_'; }

class Lexer {
 public:
  Lexer(const std::string& text, Reporter& reporter) : t_(text), reporter_(reporter) {}

  std::vector<Token> run() {
    while (true) {
      skip_space_and_comments();
      if (i_ >= t_.size()) break;
      token();
    }
    Token end;
    end.kind = Tok::End;
    end.offset = t_.size();
    end.line = line_;
    out_.push_back(end);
    return std::move(out_);
  }

 private:
  char at(size_t k) const { return k < t_.size() ? t_[k] : '\0'; }

  void skip_space_and_comments() {
    while (i_ < t_.size()) {
      const char c = t_[i_];
      if (c == '\n') {
        ++line_;
        ++i_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i_;
      } else if (c == '/' && at(i_ + 1) == '/') {
        while (i_ < t_.size() && t_[i_] != '\n') ++i_;
      } else if (c == '(' && at(i_ + 1) == '*') {
        const size_t start = i_;
        i_ += 2;
        while (i_ < t_.size() && !(t_[i_] == '*' && at(i_ + 1) == ')')) {
          if (t_[i_] == '\n') ++line_;
          ++i_;
        }
        if (i_ >= t_.size()) {
          reporter_.error(Error::OpenComment, start);
          return;
        }
        i_ += 2;
      } else {
        return;
      }
    }
  }

  Token& push(Tok kind, size_t start) {
    Token t;
    t.kind = kind;
    t.offset = start;
    t.line = line_;
    out_.push_back(std::move(t));
    return out_.back();
  }

  void token() {
    const size_t start = i_;
    const char c = t_[i_];
    if (is_letter(c)) return name(start);
    if (is_digit(c)) return number(start);
    if (c == '\'') return string(start);
    ++i_;
    const char n = at(i_);
    switch (c) {
      case ':':
        if (n == '=') {
          ++i_;
          push(Tok::Assign, start);
        } else
          push(Tok::Colon, start);
        return;
      case ';':
        push(Tok::Semi, start);
        return;
      case ',':
        push(Tok::Comma, start);
        return;
      case '(':
        push(Tok::LParen, start);
        return;
      case ')':
        push(Tok::RParen, start);
        return;
      case '+':
        push(Tok::Plus, start);
        return;
      case '-':
        push(Tok::Minus, start);
        return;
      case '*':
        push(Tok::Star, start);
        return;
      case '/':
        push(Tok::Slash, start);
        return;
      case '&':
        push(Tok::Amp, start);
        return;
      case '|':
        push(Tok::Bar, start);
        return;
      case '^':
        push(Tok::Caret, start);
        return;
      case '=':
        push(Tok::Eq, start);
        return;
      case '<':
        if (n == '=') {
          ++i_;
          push(Tok::Le, start);
        } else if (n == '>') {
          ++i_;
          push(Tok::Ne, start);
        } else if (n == '<') {
          ++i_;
          push(Tok::Shl, start);
        } else
          push(Tok::Lt, start);
        return;
      case '>':
        if (n == '=') {
          ++i_;
          push(Tok::Ge, start);
        } else if (n == '>') {
          ++i_;
          push(Tok::Shr, start);
        } else
          push(Tok::Gt, start);
        return;
      case '[':
        reporter_.error(Error::Unsupported, start, "arrays are not implemented");
        return;
      case ']':
        return;  // its '[' was reported
      default:
        reporter_.error(Error::BadCharacter, start);
        return;
    }
  }

  void name(size_t start) {
    while (i_ < t_.size() && is_name_char(t_[i_])) ++i_;
    push(Tok::Ident, start).text = t_.substr(start, i_ - start);
  }

  // 123, 16#FF, 2#101, 8#17; a fraction or exponent is a float: not supported.
  void number(size_t start) {
    int base = 10;
    while (is_digit(at(i_))) ++i_;
    if (at(i_) == '#') {
      const std::string b = t_.substr(start, i_ - start);
      base = b == "16" ? 16 : b == "2" ? 2 : b == "8" ? 8 : 0;
      ++i_;
      if (base == 0) {
        while (is_name_char(at(i_))) ++i_;
        reporter_.error(Error::Syntax, start, "a based number is 2#, 8# or 16#");
        return;
      }
    } else {
      i_ = start;
    }
    const size_t digits = i_;
    uint64_t v = 0;
    bool big = false;
    while (is_name_char(at(i_))) {
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(t_[i_])));
      const int d = is_digit(c) ? c - '0' : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : 99;
      if (c == '_') {
        ++i_;
        continue;
      }
      if (d >= base) {
        while (is_name_char(at(i_))) ++i_;
        reporter_.error(Error::Syntax, start, "not a digit of this number");
        return;
      }
      v = v * static_cast<uint64_t>(base) + static_cast<uint64_t>(d);
      if (v > 0xFFFFFFFFull) big = true, v = 0xFFFFFFFFull + 1;
      ++i_;
    }
    if (i_ == digits) {
      reporter_.error(Error::Syntax, start, "a number needs digits");
      return;
    }
    if (base == 10 && (at(i_) == '.' && is_digit(at(i_ + 1)))) {
      ++i_;
      while (is_name_char(at(i_))) ++i_;
      reporter_.error(Error::Unsupported, start, "floating point is not implemented");
      return;
    }
    Token& t = push(Tok::Number, start);
    // A decimal reaches 2147483648 only after a unary minus; a based one is a 32-bit pattern.
    if (base == 10) {
      t.number_too_big = big || v > 2147483648ull;
      t.value = static_cast<int64_t>(v);
    } else {
      t.number_too_big = big;
      t.value = static_cast<int32_t>(static_cast<uint32_t>(v));
    }
  }

  void string(size_t start) {
    ++i_;
    std::string s;
    while (i_ < t_.size() && t_[i_] != '\'' && t_[i_] != '\n') {
      char c = t_[i_++];
      if (c == '\\' && i_ < t_.size() && t_[i_] != '\n') {
        const char e = t_[i_++];
        c = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
        if (e != 'n' && e != 't' && e != 'r' && e != '\\' && e != '\'') s.push_back('\\');
      }
      s.push_back(c);
    }
    if (i_ >= t_.size() || t_[i_] != '\'') {
      reporter_.error(Error::OpenString, start);
    } else {
      ++i_;
    }
    // An open string still ends its line as a string, so the parser does not stumble on.
    push(Tok::String, start).text = std::move(s);
  }

  const std::string& t_;
  Reporter& reporter_;
  size_t i_ = 0;
  int line_ = 1;
  std::vector<Token> out_;
};

}  // namespace

std::vector<Token> lex(const std::string& text, Reporter& reporter) {
  return Lexer(text, reporter).run();
}

}  // namespace uprog::st
