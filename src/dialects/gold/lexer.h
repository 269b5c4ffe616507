// Splits preprocessed Gold text into tokens: numbers by the rules of manual 1.3, comments
// (//, ** and /* */), continuation lines (...), labels (##NAME) and auto-routine labels (#@NAME).
#pragma once
#include <string>
#include <vector>

#include "dialects/gold/reporter.h"
#include "dialects/gold/token.h"

namespace uprog::gold {

// The text must outlive the tokens (they view into it). Always ends with one Eof token.
std::vector<Token> lex(const std::string& text, Reporter& reporter);

}  // namespace uprog::gold
