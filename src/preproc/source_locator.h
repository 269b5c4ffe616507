// Turns offsets in the text a dialect's lexer reads into the user's places (file, line, column):
// through the preprocessor's source map when the text was preprocessed, else by the text's own
// line starts. The one locator every compiler uses, so that an error inside or just past a macro
// expansion is placed alike in every dialect.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "preproc/preprocess.h"
#include "support/diagnostic.h"

namespace uprog::preproc {

class SourceLocator {
 public:
  // `map` may be null (or empty): offsets are then placed in `text` itself, named `file`.
  // `text` and `map` must outlive the locator.
  SourceLocator(std::string file, std::string_view text, const SourceMap* map)
      : file_(std::move(file)), text_(text), map_(map) {}
  // Inside (or just past) a macro expansion: where the macro was used.
  Location locate(size_t offset) const;
  // A note naming the macro expansion `offset` lies in, if any.
  std::vector<DiagnosticNote> notes(size_t offset) const;
  // 1-based line of `offset` in the lexer's text.
  int text_line(size_t offset) const;
  const std::string& file() const { return file_; }

 private:
  const Expansion* expansion(size_t offset) const;

  std::string file_;
  std::string_view text_;
  const SourceMap* map_;
  // Found on the first question: a compile without errors or line table never asks.
  mutable std::vector<size_t> line_starts_;
};

}  // namespace uprog::preproc
