// Collects the compiler's errors as (code, offset, name) and turns them into located Diagnostics
// at the end: sorted by place, cut at the limit with "Too many errors" (46) as the manual has it.
// Collecting is bounded too, so that a binary file costs no more than a few hundred errors.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/gold/errors.h"
#include "preproc/source_locator.h"
#include "support/diagnostic.h"

namespace uprog::gold {

// Maps offsets of the text the lexer reads back to the user's file, line and column.
using Locator = preproc::SourceLocator;

// The compiler's stages, in the order they ran before the front end streamed: errors at one place
// are listed in this order, although the lexer now runs interleaved with the parser and the
// checker with both.
enum class Stage : uint8_t { Lex, Parse, Check };

class Reporter {
 public:
  // `limit`: the errors finish() gives before "Too many errors" (CompileOptions::max_errors).
  Reporter(const Locator& locator, size_t limit);
  // An error of the current stage (set_stage; Parse at first). `name`: the name it is about,
  // quoted after the manual's text ("No such variable 'spd'").
  void error(Error e, uint32_t offset, std::string_view name = {});
  void lex_error(Error e, uint32_t offset);
  void set_stage(Stage s) { stage_ = s; }
  // While muted, errors are dropped: a second parse of text already parsed once.
  void set_muted(bool muted) { muted_ = muted; }
  // Errors that already have a place (from the preprocessor or the line-length check).
  void add(Diagnostic d) { located_.push_back(std::move(d)); }
  size_t count() const { return pending_.size() + located_.size(); }
  bool has_errors() const { return count() > 0; }
  // The errors the front end found fill what the reporter keeps: it drops the rest, and the
  // lexer ends the text early (the manual's 46: "The compilation error buffer is full").
  bool full() const { return full_; }
  // Sorted by place; at most `limit` errors, then one "Too many errors".
  std::vector<Diagnostic> finish();

 private:
  struct Pending {
    Error code;
    Stage stage;
    uint32_t offset;
    std::string name;
  };
  void add_pending(Error e, Stage stage, uint32_t offset, std::string_view name);

  const Locator& locator_;
  size_t limit_;
  // The front end finds errors nearly in the order of their places, but not quite (a body is
  // checked after it is parsed, the top level after all bodies): it keeps this many times the
  // limit, so that the first `limit` by place are among them, and no more.
  static constexpr size_t kKeptPerShown = 32;
  size_t capacity_;
  bool full_ = false;
  Stage stage_ = Stage::Parse;
  bool muted_ = false;
  std::vector<Pending> pending_;
  std::vector<Diagnostic> located_;
};

}  // namespace uprog::gold
