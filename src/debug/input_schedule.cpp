// Parsing a launch's input changes (input_schedule.h).
#include "debug/input_schedule.h"

#include <algorithm>

#include "transcript/transcript.h"

namespace uprog::debug {

std::optional<std::vector<InputChange>> parse_input_changes(const std::vector<std::string>& items,
                                                            std::string* error) {
  std::vector<InputChange> out;
  for (const std::string& s : items) {
    const size_t eq = s.find('='), at = s.find('@');
    InputChange c;
    const bool shaped = eq == 1 && at != std::string::npos && at == eq + 2;
    if (!shaped || s[0] < '1' || s[0] > '6' || (s[2] != '0' && s[2] != '1') ||
        !transcript::parse_duration_us(s.substr(at + 1), c.at_us)) {
      if (error)
        *error =
            "input '" + s + "': expected N=LEVEL@TIME with N 1..6 and LEVEL 0 or 1, e.g. 2=1@500ms";
      return std::nullopt;
    }
    c.input = s[0] - '0';
    c.level = s[2] == '1';
    out.push_back(c);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const InputChange& a, const InputChange& b) { return a.at_us < b.at_us; });
  return out;
}

}  // namespace uprog::debug
