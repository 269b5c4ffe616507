// Mapping output offsets back to the source: two binary searches, one over expansions (sorted
// and disjoint, since only top-level uses are recorded) and one over segments.
#include <algorithm>

#include "preproc/preprocess.h"

namespace uprog::preproc {

const Expansion* SourceMap::expansion_at(size_t offset) const {
  const auto it = std::upper_bound(expansions.begin(), expansions.end(), offset,
                                   [](size_t o, const Expansion& e) { return o < e.begin; });
  if (it == expansions.begin()) return nullptr;
  const Expansion& e = *(it - 1);
  return offset < e.end ? &e : nullptr;
}

Location SourceMap::locate(size_t offset) const {
  if (const Expansion* e = expansion_at(offset)) return e->used_at;
  const auto it = std::upper_bound(segments.begin(), segments.end(), offset,
                                   [](size_t o, const Segment& s) { return o < s.out_begin; });
  if (segments.empty()) return Location{};
  if (it == segments.begin())
    return Location{file_name(segments.front().file), segments.front().line,
                    segments.front().column};
  const Segment& s = *(it - 1);
  return Location{file_name(s.file), s.line,
                  s.column + static_cast<int>(std::min<size_t>(offset - s.out_begin, 1u << 30))};
}

}  // namespace uprog::preproc
