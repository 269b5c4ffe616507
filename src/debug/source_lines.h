// The image's line table seen from the source: where a source line's code starts (a breakpoint
// on a line without code moves to the next line that has some), and whether a code word starts a
// line (where a step ends).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "bytecode/image.h"

namespace uprog::debug {

struct LinePlace {
  uint32_t pc = 0;
  uint32_t line = 0;
  std::string file;  // as the line table names it
};

// True when the two names are the same file: the same path once made absolute, or, for a table
// that names files relative to another directory, the same file name.
bool same_file(std::string_view a, std::string_view b);
// The first code word of `line` in `file`, or of the nearest later line with code.
std::optional<LinePlace> resolve_line(const bytecode::Image& image, std::string_view file,
                                      uint32_t line);
bool is_line_start(const bytecode::Image& image, uint32_t pc);

}  // namespace uprog::debug
