// PDL's tokens: the preprocessed text cut into names, numbers, strings and operators, each with
// its offset (for the source map) and whether it starts a line (a declaration ends there).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/pdl/errors.h"

namespace uprog::pdl {

enum class Tok : uint8_t { Name, Int, Float, String, Char, Op, End };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // a name, an operator, a string's characters, a number as written
  size_t offset = 0;
  size_t end = 0;  // offset after the token
  bool line_start = false;
  int32_t int_value = 0;
  float float_value = 0;
};

struct LexError {
  Error error;
  size_t offset;
  std::string detail;
};

// Comments (`//`, `/* */`) are gone after the preprocessor only where it ran; the lexer skips
// them too. The last token is End.
std::vector<Token> tokenize(std::string_view text, std::vector<LexError>& errors);

}  // namespace uprog::pdl
