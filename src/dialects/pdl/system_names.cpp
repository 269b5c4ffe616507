// The tables behind system_names.h.
#include "dialects/pdl/system_names.h"

#include <cctype>

namespace uprog::pdl {
namespace {

constexpr SystemVariable kVariables[] = {
#define SYSVAR(name, id, access, slave, length) {#name, id, access, slave, length},
#include "dialects/pdl/system_names.def"
#undef SYSVAR
};

constexpr StateName kStates[] = {
#define STATE(name, number, writable) {#name, number, writable},
#include "dialects/pdl/states.def"
#undef STATE
};

}  // namespace

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

const SystemVariable* find_system_variable(std::string_view name, bool* axis_zero) {
  if (axis_zero) *axis_zero = false;
  for (const SystemVariable& v : kVariables)
    if (equal_ignoring_case(v.name, name)) return &v;
  if (name.size() > 2 && (name[0] == 'X' || name[0] == 'x') && name[1] == '_') {
    for (const SystemVariable& v : kVariables) {
      if (v.slave && equal_ignoring_case(v.name, name.substr(2))) {
        if (axis_zero) *axis_zero = true;
        return &v;
      }
    }
  }
  return nullptr;
}

const SystemVariable* system_variable_by_id(uint32_t id) {
  for (const SystemVariable& v : kVariables)
    if (v.id == id) return &v;
  return nullptr;
}

const StateName* find_state(std::string_view name) {
  for (const StateName& s : kStates)
    if (equal_ignoring_case(s.name, name)) return &s;
  return nullptr;
}

}  // namespace uprog::pdl
