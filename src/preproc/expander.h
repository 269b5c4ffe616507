// Turns one use of a #define name into its replacement text: the value, or the string rescanned
// for other names (as in C). Bounds depth and length, so hostile defines stay finite.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "preproc/macro_table.h"
#include "preproc/preprocess.h"

namespace uprog::preproc {

class Expander {
 public:
  Expander(const MacroTable& macros, const PreprocOptions& options)
      : macros_(macros), options_(options) {}

  // Whether a use of `m` is replaced at all: a #define without a string is not (manual 2.9.1).
  static bool expands(const Macro* m) { return m && (m->value || !m->body.empty() || m->params); }

  // The replacement of a use of `name` (with its arguments when it is function-like), or
  // nullopt when it is too deep or too long.
  std::optional<std::string> expand(std::string_view name, const Macro& m,
                                    const std::vector<std::string>* args = nullptr);

  // The table changed: a name that was too complex may not be any more.
  void forget_failures() { too_complex_.clear(); }

 private:
  bool expand_body(std::string_view body, std::vector<std::string_view>& painted, int depth,
                   std::string& text) const;

  const MacroTable& macros_;
  const PreprocOptions& options_;
  size_t total_expanded_ = 0;
  std::vector<std::string> too_complex_;  // names whose expansion failed since the last change
};

// After a function-like macro's name at text[pos]: blanks, then `(` arguments `)` with nested
// parentheses and strings kept; the trimmed arguments and the offset after `)`. False when no
// `(` follows or it does not close on this text.
bool read_arguments(std::string_view text, size_t pos, std::vector<std::string>& args, size_t& end);

// The body with each parameter replaced by its argument (identifiers only, not in strings).
std::string substitute(const Macro& m, const std::vector<std::string>& args,
                       const PreprocOptions& options);

}  // namespace uprog::preproc
