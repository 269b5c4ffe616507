// PUP's debug map in JSON (debug_map.h): {"lines": [[file, line], ...], "variables": [{"name",
// "base", "size", "array"}, ...]}.
#include "dialects/pup/debug_map.h"

#include <nlohmann/json.hpp>

namespace uprog::pup {

std::string write_debug_map(const std::vector<Location>& places, const VarTable& vars) {
  nlohmann::json lines = nlohmann::json::array(), variables = nlohmann::json::array();
  for (const Location& l : places) lines.push_back({l.file, l.line});
  for (const auto& [name, v] : vars)
    variables.push_back({{"name", name}, {"base", v.base}, {"size", v.size}, {"array", v.array}});
  return nlohmann::json{{"lines", lines}, {"variables", variables}}.dump(
      -1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::optional<DebugMap> read_debug_map(std::string_view text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return std::nullopt;
  DebugMap map;
  try {
    for (const nlohmann::json& l : j.at("lines"))
      map.places.push_back(Location{l.at(0).get<std::string>(), l.at(1).get<int>(), 1});
    for (const nlohmann::json& v : j.at("variables")) {
      Var var;
      var.base = v.at("base").get<int32_t>();
      var.size = v.at("size").get<int32_t>();
      var.array = v.at("array").get<bool>();
      map.vars[v.at("name").get<std::string>()] = var;
    }
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  return map;
}

}  // namespace uprog::pup
