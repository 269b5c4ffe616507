// The tokens of Gold source text. A token keeps its offset into the preprocessed text; the
// compiler maps offsets back to the user's file, line and column only when it reports.
#pragma once
#include <cstdint>
#include <string_view>

#include "dialects/gold/keywords.h"

namespace uprog::gold {

enum class Tok : uint8_t {
  Ident, Int, Float,
  Label,      // ##NAME (the text is NAME)
  AutoLabel,  // #@NAME
  Newline, Semicolon, Comma, Colon,
  LParen, RParen, LBracket, RBracket,
  Plus, Minus, Star, Slash, Percent, Tilde, Bang,
  Shl, Shr, Lt, Le, Gt, Ge, EqEq, Ne, Amp, Pipe, AndAnd, OrOr,
  Assign, PlusPlus, MinusMinus,
  Unknown,  // a character Gold has no use for
  Eof,
};

struct Token {
  Tok kind = Tok::Eof;
  Keyword kw = Keyword::None;  // for an Ident: the keyword it spells, found once by the lexer
  uint32_t offset = 0;  // into the preprocessed text
  std::string_view text;  // the spelling; for labels the name without ## or #@
  int32_t int_value = 0;
  float float_value = 0.0f;
};

const char* tok_spelling(Tok t);

}  // namespace uprog::gold
