// The tokens of Gold source text. A token keeps its offset into the preprocessed text; the
// compiler maps offsets back to the user's file, line and column only when it reports. Tokens
// are 16 bytes and made one at a time (lexer.h): the parser never holds a file's worth of them.
#pragma once
#include <cstdint>
#include <string_view>

#include "dialects/gold/keywords.h"

namespace uprog::gold {

enum class Tok : uint8_t {
  Ident,
  Int,
  Float,
  Label,      // ##NAME (the text is NAME)
  AutoLabel,  // #@NAME
  Newline,
  Semicolon,
  Comma,
  Colon,
  LParen,
  RParen,
  LBracket,
  RBracket,
  Plus,
  Minus,
  Star,
  Slash,
  Percent,
  Tilde,
  Bang,
  Shl,
  Shr,
  Lt,
  Le,
  Gt,
  Ge,
  EqEq,
  Ne,
  Amp,
  Pipe,
  AndAnd,
  OrOr,
  Assign,
  PlusPlus,
  MinusMinus,
  Unknown,  // a character Gold has no use for
  Eof,
};

struct Token {
  Tok kind = Tok::Eof;
  Keyword kw = Keyword::None;  // for an Ident: the keyword it spells, found once by the lexer
  uint8_t name_skip = 0;       // labels: the characters before the name ("##", "#@" or "#")
  uint32_t offset = 0;         // into the preprocessed text
  uint32_t length = 0;         // of the spelling, from `offset`
  union {
    int32_t int_value = 0;  // Int
    float float_value;      // Float
  };

  // The spelling in `text` (the lexer's); for labels the name without ## or #@.
  std::string_view text(std::string_view source) const {
    return source.substr(offset + name_skip, length - name_skip);
  }
};
static_assert(sizeof(Token) == 16, "tokens are made and copied one at a time; keep them small");

const char* tok_spelling(Tok t);

// Where the lexer stands; restoring it reads the same tokens again (a function body that the
// compiler parses a second time).
struct LexState {
  uint32_t pos = 0;
  uint32_t clause_start = 0;
  Tok last = Tok::Newline;  // Newline also before the first token: no empty line is a token
  bool at_end = false;      // the final Newline is out; only Eof remains
};

}  // namespace uprog::gold
