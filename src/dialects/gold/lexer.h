// Splits preprocessed Gold text into tokens, one at a time, as the parser asks for them: numbers
// by the rules of manual 1.3, comments (//, ** and /* */), continuation lines (...), labels
// (##NAME) and auto-routine labels (#@NAME). No token list is ever built.
#pragma once
#include <cstdint>
#include <string_view>

#include "dialects/gold/reporter.h"
#include "dialects/gold/token.h"

namespace uprog::gold {

class Lexer {
 public:
  // The text must outlive the lexer and its tokens (they hold offsets into it).
  Lexer(std::string_view text, Reporter& reporter) : s_(text), r_(reporter) {}

  // The next token; after the last one, Eof forever.
  Token next();

  std::string_view text() const { return s_; }
  LexState state() const { return st_; }
  void restore(const LexState& s) { st_ = s; }

 private:
  bool newline(size_t at, Token& out);
  bool skip_blank(Token& out);
  void continuation();
  Token number();
  Token punct();
  Token make(Tok k, size_t b, size_t n);

  std::string_view s_;
  Reporter& r_;
  LexState st_;
};

}  // namespace uprog::gold
