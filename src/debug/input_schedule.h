// The digital inputs a launch changes at given times ("2=1@500ms", as `uprog run --input`),
// applied as virtual time reaches them.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace uprog::debug {

struct InputChange {
  uint64_t at_us = 0;
  int input = 1;
  bool level = false;
};

// Sorted by time; nullopt with `error` set when an item is not N=LEVEL@TIME (N 1..6, LEVEL 0|1).
std::optional<std::vector<InputChange>> parse_input_changes(const std::vector<std::string>& items,
                                                            std::string* error);

}  // namespace uprog::debug
