// The built-in function table.
#include "dialects/gold/builtins.h"

#include <array>

namespace uprog::gold {

namespace {
constexpr std::array<BuiltinInfo, 14> kBuiltins = {{
    {"sin", Builtin::Sin, BuiltinResult::Fixed, Kind::Float},
    {"cos", Builtin::Cos, BuiltinResult::Fixed, Kind::Float},
    {"abs", Builtin::Abs, BuiltinResult::SameAsInput, Kind::None},
    {"sqrt", Builtin::Sqrt, BuiltinResult::Fixed, Kind::Float},
    {"fix", Builtin::Fix, BuiltinResult::Fixed, Kind::Int},
    {"rnd", Builtin::Rnd, BuiltinResult::Fixed, Kind::Int},
    {"sign", Builtin::Sign, BuiltinResult::Fixed, Kind::Int},
    {"real", Builtin::Real, BuiltinResult::Fixed, Kind::Float},
    {"tdif", Builtin::Tdif, BuiltinResult::Fixed, Kind::Int},
    {"prgerr", Builtin::Prgerr, BuiltinResult::Fixed, Kind::Int},
    {"tick", Builtin::Tick, BuiltinResult::Fixed, Kind::Int},
    {"tock", Builtin::Tock, BuiltinResult::Fixed, Kind::Int},
    {"utick", Builtin::Utick, BuiltinResult::Fixed, Kind::Int},
    {"utock", Builtin::Utock, BuiltinResult::Fixed, Kind::Int},
}};
}  // namespace

const BuiltinInfo* find_builtin(std::string_view name) {
  if (name.size() < 3 || name.size() > 6) return nullptr;  // "sin" .. "prgerr"
  for (const BuiltinInfo& b : kBuiltins)
    if (b.name == name) return &b;
  return nullptr;
}

const BuiltinInfo* builtin_info(Builtin id) {
  for (const BuiltinInfo& b : kBuiltins)
    if (b.id == id) return &b;
  return &kBuiltins[0];
}

}  // namespace uprog::gold
