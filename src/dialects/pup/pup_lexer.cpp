// Splitting a PUP line into tokens (pup_lexer.h).
#include "dialects/pup/pup_lexer.h"

#include <cctype>

#include "dialects/pup/errors.h"

namespace uprog::pup {
namespace {

constexpr const char* kTwoCharOps[] = {"==", "!=", "<=", ">=", "<<", ">>", "&&", "||"};
constexpr std::string_view kOneCharOps = "()[],=<>+-*/%&|^~!";

}  // namespace

std::optional<std::vector<Token>> tokenize(const std::string& text, const Location& line_start,
                                           std::vector<Diagnostic>& diagnostics) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    Location at = line_start;
    at.column = line_start.column + static_cast<int>(i);
    if (c == ' ' || c == '\t') {
      ++i;
      continue;
    }
    size_t j = i;
    TokenKind kind = TokenKind::Op;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (j < text.size() && is_name_char(text[j])) ++j;
      kind = TokenKind::Name;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      while (j < text.size() && is_name_char(text[j])) ++j;
      kind = TokenKind::Number;
    } else {
      for (const char* op : kTwoCharOps) {
        if (text.compare(i, 2, op) == 0) j = i + 2;
      }
      if (j == i && kOneCharOps.find(c) != std::string_view::npos) j = i + 1;
      if (j == i) {
        diagnostics.push_back(
            make_error(Error::Syntax, at, std::string("unexpected character '") + c + "'"));
        return std::nullopt;
      }
    }
    out.push_back({kind, text.substr(i, j - i), at});
    i = j;
  }
  return out;
}

}  // namespace uprog::pup
