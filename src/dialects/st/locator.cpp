// Offsets to places (locator.h).
#include "dialects/st/locator.h"

#include <algorithm>

namespace uprog::st {

Locator::Locator(std::string file, const std::string& text, const preproc::SourceMap* map)
    : file_(std::move(file)), map_(map) {
  line_starts_.push_back(0);
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') line_starts_.push_back(i + 1);
}

Location Locator::at(size_t offset) const {
  if (map_ != nullptr) {
    Location l = map_->locate(offset);
    l.file = file_;
    return l;
  }
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const size_t line = static_cast<size_t>(it - line_starts_.begin());
  return Location{file_, static_cast<int>(line),
                  static_cast<int>(offset - line_starts_[line - 1]) + 1};
}

}  // namespace uprog::st
