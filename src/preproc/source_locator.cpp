// Offsets to the user's places (source_locator.h).
#include "preproc/source_locator.h"

#include <algorithm>

namespace uprog::preproc {

int SourceLocator::text_line(size_t offset) const {
  if (line_starts_.empty()) {
    line_starts_.push_back(0);
    for (size_t i = text_.find('\n'); i != std::string_view::npos; i = text_.find('\n', i + 1))
      line_starts_.push_back(i + 1);
  }
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  return static_cast<int>(it - line_starts_.begin());
}

const Expansion* SourceLocator::expansion(size_t offset) const {
  if (map_ == nullptr) return nullptr;
  if (const Expansion* e = map_->expansion_at(offset)) return e;
  // An error found just past an expansion's last character ("a = SPEED" with "5 +") is the
  // expansion's too.
  if (offset == 0) return nullptr;
  const Expansion* e = map_->expansion_at(offset - 1);
  return e != nullptr && e->end == offset ? e : nullptr;
}

Location SourceLocator::locate(size_t offset) const {
  if (const Expansion* e = expansion(offset)) return e->used_at;
  if (map_ != nullptr && !map_->segments.empty()) return map_->locate(offset);
  const int line = text_line(offset);
  return Location{file_, line,
                  static_cast<int>(offset - line_starts_[static_cast<size_t>(line - 1)]) + 1};
}

std::vector<DiagnosticNote> SourceLocator::notes(size_t offset) const {
  const Expansion* e = expansion(offset);
  if (e == nullptr) return {};
  return {{e->defined_at, "in the expansion of '" + e->macro + "', defined here"}};
}

}  // namespace uprog::preproc
