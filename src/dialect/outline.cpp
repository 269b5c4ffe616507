// Words of a source outside comments and strings (outline.h).
#include "dialect/outline.h"

#include <algorithm>
#include <cctype>

namespace uprog::dialect {
namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

}  // namespace

std::vector<SourceWord> source_words(std::string_view text, const WordSyntax& syntax) {
  std::vector<SourceWord> words;
  int line = 1;
  size_t line_begin = 0;
  bool first_on_line = true;
  size_t i = 0;
  auto newline = [&](size_t at) {
    ++line;
    line_begin = at + 1;
    first_on_line = true;
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      newline(i);
      ++i;
    } else if ((syntax.slash_slash_comments && text.compare(i, 2, "//") == 0) ||
               (syntax.star_star_comments && text.compare(i, 2, "**") == 0)) {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if ((syntax.block_comments && text.compare(i, 2, "/*") == 0) ||
               (syntax.paren_star_comments && text.compare(i, 2, "(*") == 0)) {
      const std::string_view close = text[i] == '/' ? "*/" : "*)";
      i += 2;
      while (i < text.size() && text.compare(i, 2, close) != 0) {
        if (text[i] == '\n') newline(i);
        ++i;
      }
      i = std::min(text.size(), i + 2);
    } else if (syntax.string_quote != 0 && c == syntax.string_quote) {
      ++i;
      while (i < text.size() && text[i] != syntax.string_quote && text[i] != '\n') {
        if (text[i] == '\\') ++i;
        ++i;
      }
      if (i < text.size() && text[i] == syntax.string_quote) ++i;
      first_on_line = false;
    } else if (word_char(c) || (syntax.hash_starts_word && c == '#')) {
      const size_t begin = i;
      ++i;
      while (i < text.size() && (word_char(text[i]) || (c == '#' && text[i] == '#') ||
                                 (c == '#' && text[i] == '@' && i == begin + 1)))
        ++i;
      SourceWord w;
      w.text = text.substr(begin, i - begin);
      w.line = line;
      w.column = static_cast<int>(begin - line_begin) + 1;
      w.offset = begin;
      w.line_start = first_on_line;
      size_t after = i;
      while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
      w.next = after < text.size() ? text[after] : '\n';
      if (w.next == '\r') w.next = '\n';
      first_on_line = false;
      if (w.text != "#") words.push_back(w);
    } else {
      if (c != ' ' && c != '\t' && c != '\r') first_on_line = false;
      ++i;
    }
  }
  return words;
}

std::vector<std::pair<std::string_view, size_t>> declared_names(std::string_view rest) {
  std::vector<std::pair<std::string_view, size_t>> names;
  int depth = 0;
  bool expect_name = true;
  for (size_t i = 0; i < rest.size();) {
    const char c = rest[i];
    if (c == '\n' || c == ';' || rest.compare(i, 2, "//") == 0 || rest.compare(i, 2, "(*") == 0)
      break;
    if (c == '[' || c == '(') {
      ++depth;
    } else if (c == ']' || c == ')') {
      depth = std::max(depth - 1, 0);
    } else if (c == ',' && depth == 0) {
      expect_name = true;
    } else if (depth == 0 && expect_name &&
               (std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_')) {
      const size_t begin = i;
      while (i < rest.size() && word_char(rest[i])) ++i;
      names.emplace_back(rest.substr(begin, i - begin), begin);
      expect_name = false;
      continue;
    }
    ++i;
  }
  return names;
}

std::string_view rest_of_line(std::string_view text, size_t offset) {
  if (offset > text.size()) return {};
  const size_t end = text.find('\n', offset);
  return text.substr(offset, end == std::string_view::npos ? std::string_view::npos : end - offset);
}

}  // namespace uprog::dialect
