// PUP's tokens: one source line into names, numbers and operators, each with its place.
#pragma once
#include <cctype>
#include <optional>
#include <string>
#include <vector>

#include "support/diagnostic.h"

namespace uprog::pup {

enum class TokenKind { Name, Number, Op };

// A letter, a digit or '_': what names (and the names inside messages) are made of.
inline bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

struct Token {
  TokenKind kind = TokenKind::Op;
  std::string text;
  Location where;
};

// Tokens of `text` (a line without its comment); a character no token starts with gives a
// Syntax diagnostic.
std::optional<std::vector<Token>> tokenize(const std::string& text, const Location& line_start,
                                           std::vector<Diagnostic>& diagnostics);

}  // namespace uprog::pup
