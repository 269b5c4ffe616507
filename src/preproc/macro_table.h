// The identifiers #define has defined, in force at the current line. A value that the string
// evaluates to is computed once, at the #define (manual 2.9.1), so uses never re-evaluate.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/source.h"
#include "support/value.h"

namespace uprog::preproc {

struct Macro {
  std::string body;                 // the string, comments blanked and trimmed; may be empty
  std::optional<TypedValue> value;  // set when the body is a constant expression
  Location defined_at;
  std::optional<std::vector<std::string>> params;  // a function-like macro's (HIWIN PDL)
};

class MacroTable {
 public:
  const Macro* find(std::string_view name) const {
    const auto it = macros_.find(name);
    return it == macros_.end() ? nullptr : &it->second;
  }
  bool empty() const { return macros_.empty(); }
  void define(std::string name, Macro m) {
    macros_.insert_or_assign(std::move(name), std::move(m));
  }
  bool undefine(std::string_view name) {
    const auto it = macros_.find(name);
    if (it == macros_.end()) return false;
    macros_.erase(it);
    return true;
  }

 private:
  std::map<std::string, Macro, std::less<>> macros_;
};

}  // namespace uprog::preproc
