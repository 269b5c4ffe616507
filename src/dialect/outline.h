// What a dialect tells an editor about a source without compiling it: its declarations (an
// outline: functions, tasks, labels, variables, macros, with their places and scopes), found
// over the source's words (comments and strings skipped as the dialect writes them).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace uprog::dialect {

enum class SymbolKind : uint8_t { Function, Task, Label, Variable, Parameter, Macro };

struct SourceSymbol {
  std::string name;
  SymbolKind kind = SymbolKind::Variable;
  std::string detail;  // its type or form: "int", "float[10]", "function [x] = f(a)"
  int line = 0;        // 1-based: where the name is declared
  int column = 0;      // 1-based, in bytes
  int end_line = 0;    // a function's, task's or program's last line; `line` for the others
  std::string scope;   // the function or task a local or label belongs to; "" for globals
};

// An identifier-like run of a source outside comments and strings.
struct SourceWord {
  std::string_view text;
  int line = 0, column = 0;  // 1-based, column in bytes
  size_t offset = 0;
  bool line_start = false;  // the first word on its line
  char next = '\0';         // the first character after it that is not a blank ('\n' at the end)
};

struct WordSyntax {
  bool slash_slash_comments = true;  // `// to the end of the line`
  bool block_comments = true;        // `/* ... */`
  bool paren_star_comments = false;  // `(* ... *)` (IEC 61131-3)
  bool star_star_comments = false;   // `** to the end of the line` (Gold's command line)
  char string_quote = '"';           // 0: none
  bool hash_starts_word = true;      // `#define`, `##LABEL` are words
};

std::vector<SourceWord> source_words(std::string_view text, const WordSyntax& syntax);

// The names a declaration lists, "a, b[4], c" (stopping at a comment, ';' or the line's end):
// each name and its offset in `rest`; what stands in brackets is skipped.
std::vector<std::pair<std::string_view, size_t>> declared_names(std::string_view rest);
// The line of `text` that holds `offset`, from `offset` to its end.
std::string_view rest_of_line(std::string_view text, size_t offset);

}  // namespace uprog::dialect
