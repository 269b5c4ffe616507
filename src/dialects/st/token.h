// The tokens of ST source: what the lexer makes of the preprocessed text, each with its offset
// in that text (the SourceLocator turns it into the user's file, line and column).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace uprog::st {

enum class Tok : uint8_t {
  End,
  Ident,
  Number,
  String,
  Assign,
  Colon,
  Semi,
  Comma,
  LParen,
  RParen,
  Plus,
  Minus,
  Star,
  Slash,
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  Amp,
  Bar,
  Caret,
  Shl,
  Shr,
};

struct Token {
  Tok kind = Tok::End;
  std::string text;   // an identifier as written; a string's contents with escapes resolved
  int64_t value = 0;  // a number
  bool number_too_big = false;  // beyond 32 bits (a decimal beyond 2147483648)
  size_t offset = 0;
  int line = 0;  // the line in the preprocessed text (1-based), as in the source
};

}  // namespace uprog::st
