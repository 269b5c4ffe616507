// Gold's reserved words (manual 2.3, plus nargout) and its auto-routine names (2.14). Keywords
// are matched without regard to case because the manual itself writes "Return", "If", "Try".
#pragma once
#include <cstdint>
#include <string_view>

namespace uprog::gold {

enum class Keyword : uint8_t {
  None,
  Break,
  Case,
  Catch,
  Continue,
  Else,
  Elseif,
  End,
  Exit,
  Float,
  For,
  Function,
  Global,
  Goto,
  If,
  Int,
  Otherwise,
  Reset,
  Return,
  Switch,
  Try,
  Until,
  Wait,
  While,
  Nargout,
};

Keyword keyword_of(std::string_view word);

// The protected auto-routine names, with the event number the image records for each
// (the bit of MI that masks it, as a bit index; AUTO_PERR, which cannot be masked, is 15).
struct AutoRoutineName {
  std::string_view name;
  uint32_t event;
};
// Case-sensitive, as the manual spells them; nullptr when `name` is not one.
const AutoRoutineName* find_auto_routine(std::string_view name);

}  // namespace uprog::gold
