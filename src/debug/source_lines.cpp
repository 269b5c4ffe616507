// Line table look-ups for the debugger (source_lines.h).
#include "debug/source_lines.h"

#include <algorithm>
#include <filesystem>

namespace uprog::debug {

bool same_file(std::string_view a, std::string_view b) {
  if (a == b) return true;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path pa = fs::weakly_canonical(fs::path(a), ec);
  const fs::path pb = fs::weakly_canonical(fs::path(b), ec);
  if (!ec && pa == pb) return true;
  return fs::path(a).filename() == fs::path(b).filename();
}

std::optional<LinePlace> resolve_line(const bytecode::Image& image, std::string_view file,
                                      uint32_t line) {
  const bytecode::LineEntry* best = nullptr;
  for (const bytecode::LineEntry& e : image.lines) {
    if (e.line < line || !same_file(e.file, file)) continue;
    // The nearest line at or after the one asked for; its first code word.
    if (best == nullptr || e.line < best->line || (e.line == best->line && e.code < best->code))
      best = &e;
  }
  if (best == nullptr) return std::nullopt;
  return LinePlace{best->code, best->line, best->file};
}

bool is_line_start(const bytecode::Image& image, uint32_t pc) {
  const auto it =
      std::lower_bound(image.lines.begin(), image.lines.end(), pc,
                       [](const bytecode::LineEntry& e, uint32_t p) { return e.code < p; });
  return it != image.lines.end() && it->code == pc;
}

}  // namespace uprog::debug
