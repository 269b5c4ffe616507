// Collects the compiler's errors as (code, offset) and turns them into located Diagnostics at
// the end: sorted by place, cut at the limit with "Too many errors" (46) as the manual has it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dialects/gold/errors.h"
#include "preproc/preprocess.h"
#include "support/diagnostic.h"

namespace uprog::gold {

// Maps offsets of the text the lexer reads back to the user's file, line and column.
class Locator {
 public:
  // `map` may be null: then offsets are located in `text` itself, named `file`.
  Locator(std::string file, const std::string& text, const preproc::SourceMap* map);
  // Inside (or just past) a macro expansion: where the macro was used.
  Location locate(uint32_t offset) const;
  // A note naming the macro expansion `offset` lies in, if any.
  std::vector<DiagnosticNote> notes(uint32_t offset) const;
  // 1-based line of `offset` in the lexer's text (for the line table when there is no map).
  int text_line(uint32_t offset) const;

 private:
  const preproc::Expansion* expansion(uint32_t offset) const;

  std::string file_;
  const preproc::SourceMap* map_;
  std::vector<uint32_t> line_starts_;
};

class Reporter {
 public:
  explicit Reporter(const Locator& locator) : locator_(locator) {}
  void error(Error e, uint32_t offset, std::string detail = {});
  // Errors that already have a place (from the preprocessor or the line-length check).
  void add(Diagnostic d) { located_.push_back(std::move(d)); }
  size_t count() const { return pending_.size() + located_.size(); }
  bool has_errors() const { return count() > 0; }
  // Sorted by place; at most `limit` errors, then one "Too many errors".
  std::vector<Diagnostic> finish(size_t limit);

 private:
  struct Pending {
    Error code;
    uint32_t offset;
    std::string detail;
  };
  const Locator& locator_;
  std::vector<Pending> pending_;
  std::vector<Diagnostic> located_;
};

}  // namespace uprog::gold
