// The AG300 controller's keywords (docs/dialects/pup.md, the spec's tables): name, what it is,
// its attributes and its index and argument. The one table the PUP compiler, the CUP loader and
// the command line all read.
#pragma once
#include <cstdint>
#include <string_view>

namespace uprog::pup {

enum class KeywordId : uint16_t {
#define PUP_KEYWORD(id, name, kind, attrs, index_min, index_max, arg) id,
#include "dialects/pup/keywords.def"
#undef PUP_KEYWORD
  kCount
};

enum class KeywordKind : uint8_t {
  Param,     // read and assigned
  ReadOnly,  // read only (r)
  Command,   // runs (cmd)
  Cup,       // a CUP stack or flow keyword (executes, on a thread's stacks)
  Marker,    // AProgTask / AProgFunc: not executed
};

// Attribute bits: where and when a keyword is accepted (the spec's C, P, U, M).
constexpr uint8_t kOverLine = 1;      // C: over the line (else error 13)
constexpr uint8_t kInProgram = 2;     // P: in a program (else 14, at load)
constexpr uint8_t kNeedsProgram = 4;  // U: needs a program (15)
constexpr uint8_t kNotInMotion = 8;   // M: not during motion (20)

enum class ArgKind : uint8_t {
  None,    // no `,argument` (8 when given)
  Number,  // `,n` required (9 when missing)
  Name,    // `,AKey[i]`: a parameter's name (APushParam, APopParam)
};

struct Keyword {
  KeywordId id;
  std::string_view name;  // the spelling the CUP file uses
  KeywordKind kind;
  uint8_t attrs;
  int32_t index_min, index_max;  // index_max 0: no index
  ArgKind arg;
  bool indexed() const { return index_max != 0; }
};

// Case-insensitive, as the wire and CUP read keywords; nullptr for none.
const Keyword* find_keyword(std::string_view name);
const Keyword& keyword(KeywordId id);

}  // namespace uprog::pup
