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
  Expander(const MacroTable& macros, const PreprocOptions& options) : macros_(macros), options_(options) {}

  // Whether a use of `m` is replaced at all: a #define without a string is not (manual 2.9.1).
  static bool expands(const Macro* m) { return m && (m->value || !m->body.empty()); }

  // The replacement of a use of `name`, or nullopt when it is too deep or too long.
  std::optional<std::string> expand(std::string_view name, const Macro& m);

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

}  // namespace uprog::preproc
