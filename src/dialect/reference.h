// A dialect's reference for editors: one entry per drive command, keyword, built-in function and
// system variable, with what it is, its unit and range, its access and the manual section it
// comes from. The language server's hover and completion read it (Dialect::reference()).
#pragma once
#include <cstdint>
#include <string>

namespace uprog::dialect {

enum class ReferenceKind : uint8_t {
  Command,         // a drive command or parameter (Gold's PX, the S300's ACC)
  SystemVariable,  // a variable or state the drive keeps (PDL's vel_max, X_run)
  Function,        // a built-in function (sin, tdif)
  Keyword,         // a word of the language (while, END_IF)
  Directive,       // a preprocessor directive (#define)
  Constant,        // a name the dialect gives a number (PUP's akribis.puh: MOTOR_READY is 8)
};

struct ReferenceEntry {
  std::string name;  // as the manual writes it
  ReferenceKind kind = ReferenceKind::Keyword;
  std::string summary;    // what it is, one or two sentences
  std::string unit;       // "counts/s"; "" when it has none
  std::string range;      // "1 to 2147483647", "index 1..6"; "" when none is stated
  std::string access;     // "read/write", "read only", "action", "host only"; "" for words
  std::string source;     // the manual section or reference it comes from
  std::string signature;  // a function's call form, "sin(x)"; "" otherwise
};

}  // namespace uprog::dialect
