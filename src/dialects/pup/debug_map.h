// PUP's debug map (X.cup.json): the PUP place of every CUP line and the #definevar names with
// their AGenData slots, so that the debugger speaks of the PUP source while the drive runs CUP.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "dialects/pup/pup_expr.h"
#include "support/diagnostic.h"

namespace uprog::pup {

struct DebugMap {
  std::vector<Location> places;  // per CUP line from 1 (places[0] is line 1)
  VarTable vars;
};

std::string write_debug_map(const std::vector<Location>& places, const VarTable& vars);
// nullopt when the text is not such a map.
std::optional<DebugMap> read_debug_map(std::string_view text);

}  // namespace uprog::pup
