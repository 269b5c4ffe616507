// Gold's built-in functions (manual 1.7 and 1.12): names (case-sensitive), argument and result
// kinds. The code generator maps each to VM primitives.
#pragma once
#include <string_view>

#include "dialects/gold/ast.h"

namespace uprog::gold {

enum class BuiltinResult : uint8_t { Fixed, SameAsInput };

struct BuiltinInfo {
  std::string_view name;
  Builtin id;
  BuiltinResult result;
  Kind kind;  // the result's kind when Fixed
};

const BuiltinInfo* find_builtin(std::string_view name);
const BuiltinInfo* builtin_info(Builtin id);

}  // namespace uprog::gold
