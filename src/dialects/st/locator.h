// Turns offsets in the text the lexer reads into the user's places (file, line, column),
// through the preprocessor's source map when the text was preprocessed.
#pragma once
#include <string>
#include <vector>

#include "preproc/preprocess.h"
#include "support/source.h"

namespace uprog::st {

class Locator {
 public:
  Locator(std::string file, const std::string& text, const preproc::SourceMap* map);
  Location at(size_t offset) const;
  Location line_start(int line) const { return Location{file_, line, 1}; }

 private:
  std::string file_;
  std::vector<size_t> line_starts_;
  const preproc::SourceMap* map_;
};

}  // namespace uprog::st
