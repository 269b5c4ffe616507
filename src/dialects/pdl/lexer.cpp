// The PDL tokenizer (lexer.h).
#include "dialects/pdl/lexer.h"

#include <cctype>
#include <charconv>
#include <cstdlib>

namespace uprog::pdl {
namespace {

bool name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Longest first: the two-character operators.
constexpr std::string_view kTwoChar[] = {
    "+=", "-=", "*=", "/=", "&=", "|=", "@=", "%=", "<=", ">=", "<>", "->", "++", "--"};

class Lexer {
 public:
  Lexer(std::string_view text, std::vector<LexError>& errors) : t_(text), errors_(errors) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    bool line_start = true;
    while (true) {
      line_start = skip_blanks(line_start);
      if (i_ >= t_.size()) break;
      Token tok;
      tok.offset = i_;
      tok.line_start = line_start;
      line_start = false;
      if (!one(tok)) continue;
      tok.end = i_;
      out.push_back(std::move(tok));
    }
    Token end;
    end.offset = end.end = t_.size();
    end.line_start = true;
    out.push_back(end);
    return out;
  }

 private:
  bool skip_blanks(bool line_start) {
    while (i_ < t_.size()) {
      const char c = t_[i_];
      if (c == '\n') {
        line_start = true;
        ++i_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i_;
      } else if (c == '/' && i_ + 1 < t_.size() && t_[i_ + 1] == '/') {
        while (i_ < t_.size() && t_[i_] != '\n') ++i_;
      } else if (c == '/' && i_ + 1 < t_.size() && t_[i_ + 1] == '*') {
        const size_t close = t_.find("*/", i_ + 2);
        for (size_t k = i_; k < (close == std::string_view::npos ? t_.size() : close); ++k)
          if (t_[k] == '\n') line_start = true;
        i_ = close == std::string_view::npos ? t_.size() : close + 2;
      } else {
        break;
      }
    }
    return line_start;
  }

  bool one(Token& tok) {
    const char c = t_[i_];
    if (name_start(c)) {
      const size_t s = i_;
      while (i_ < t_.size() && name_char(t_[i_])) ++i_;
      tok.kind = Tok::Name;
      tok.text = std::string(t_.substr(s, i_ - s));
      return true;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i_ + 1 < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_ + 1])))) {
      return number(tok);
    }
    if (c == '"') return string(tok);
    if (c == '\'') return character(tok);
    for (std::string_view op : kTwoChar) {
      if (t_.substr(i_, 2) == op) {
        tok.kind = Tok::Op;
        tok.text = std::string(op);
        i_ += 2;
        return true;
      }
    }
    if (std::string_view("+-*/&|@%~<>=()[]{},;:#!").find(c) != std::string_view::npos) {
      tok.kind = Tok::Op;
      tok.text = std::string(1, c);
      ++i_;
      return true;
    }
    errors_.push_back({Error::BadCharacter, i_, std::string(1, c)});
    ++i_;
    return false;
  }

  bool number(Token& tok) {
    const size_t s = i_;
    if (t_[i_] == '0' && i_ + 1 < t_.size() && (t_[i_ + 1] == 'x' || t_[i_ + 1] == 'X')) {
      i_ += 2;
      while (i_ < t_.size() && std::isxdigit(static_cast<unsigned char>(t_[i_]))) ++i_;
      tok.text = std::string(t_.substr(s, i_ - s));
      uint32_t v = 0;
      const auto [p, e] = std::from_chars(t_.data() + s + 2, t_.data() + i_, v, 16);
      if (e != std::errc() || p != t_.data() + i_ || (i_ < t_.size() && name_char(t_[i_]))) {
        while (i_ < t_.size() && name_char(t_[i_])) ++i_;
        errors_.push_back({Error::BadNumber, s, std::string(t_.substr(s, i_ - s))});
        return false;
      }
      tok.kind = Tok::Int;
      tok.int_value = static_cast<int32_t>(v);
      return true;
    }
    bool is_float = false;
    while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) ++i_;
    if (i_ < t_.size() && t_[i_] == '.') {
      is_float = true;
      ++i_;
      while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) ++i_;
    }
    if (i_ < t_.size() && (t_[i_] == 'e' || t_[i_] == 'E')) {
      size_t k = i_ + 1;
      if (k < t_.size() && (t_[k] == '+' || t_[k] == '-')) ++k;
      if (k < t_.size() && std::isdigit(static_cast<unsigned char>(t_[k]))) {
        is_float = true;
        i_ = k;
        while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) ++i_;
      }
    }
    tok.text = std::string(t_.substr(s, i_ - s));
    if (i_ < t_.size() && name_char(t_[i_])) {
      // `00AB0103` (a printl mode) is one token: the parser reads it as hex.
      while (i_ < t_.size() && name_char(t_[i_])) ++i_;
      tok.text = std::string(t_.substr(s, i_ - s));
      tok.kind = Tok::Name;
      return true;
    }
    if (is_float) {
      tok.kind = Tok::Float;
      tok.float_value = std::strtof(tok.text.c_str(), nullptr);
      return true;
    }
    uint64_t v = 0;
    const auto [p, e] = std::from_chars(t_.data() + s, t_.data() + i_, v, 10);
    if (e != std::errc() || v > 0xFFFFFFFFull) {
      errors_.push_back({Error::BadNumber, s, tok.text});
      return false;
    }
    tok.kind = Tok::Int;
    tok.int_value = static_cast<int32_t>(static_cast<uint32_t>(v));
    return true;
  }

  bool string(Token& tok) {
    const size_t s = i_++;
    std::string text;
    while (i_ < t_.size() && t_[i_] != '"' && t_[i_] != '\n') text.push_back(t_[i_++]);
    if (i_ >= t_.size() || t_[i_] != '"') {
      errors_.push_back({Error::UnterminatedString, s, {}});
      return false;
    }
    ++i_;
    tok.kind = Tok::String;
    tok.text = std::move(text);
    return true;
  }

  bool character(Token& tok) {
    const size_t s = i_;
    if (i_ + 2 < t_.size() && t_[i_ + 2] == '\'') {
      tok.kind = Tok::Char;
      tok.int_value = static_cast<unsigned char>(t_[i_ + 1]);
      tok.text = std::string(t_.substr(s, 3));
      i_ += 3;
      return true;
    }
    errors_.push_back({Error::BadCharacter, s, "'"});
    ++i_;
    return false;
  }

  std::string_view t_;
  size_t i_ = 0;
  std::vector<LexError>& errors_;
};

}  // namespace

std::vector<Token> tokenize(std::string_view text, std::vector<LexError>& errors) {
  return Lexer(text, errors).run();
}

}  // namespace uprog::pdl
