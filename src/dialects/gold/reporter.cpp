// Locating and ordering the compiler's errors.
#include "dialects/gold/reporter.h"

#include <algorithm>
#include <cstdint>

namespace uprog::gold {

Reporter::Reporter(const Locator& locator, size_t limit)
    : locator_(locator),
      limit_(limit),
      capacity_(limit >= SIZE_MAX / kKeptPerShown - 1
                    ? SIZE_MAX
                    : std::max<size_t>(limit, 1) * kKeptPerShown + 1) {}

void Reporter::error(Error e, uint32_t offset, std::string_view name) {
  add_pending(e, stage_, offset, name);
}

void Reporter::lex_error(Error e, uint32_t offset) { add_pending(e, Stage::Lex, offset, {}); }

void Reporter::add_pending(Error e, Stage stage, uint32_t offset, std::string_view name) {
  if (muted_ || full_) return;
  // One error per place is enough: recovery may meet the same bad token twice. The search is
  // bounded by the capacity.
  for (const Pending& p : pending_)
    if (p.offset == offset && p.code == e) return;
  pending_.push_back({e, stage, offset, std::string(name)});
  full_ = pending_.size() >= capacity_;
}

std::vector<Diagnostic> Reporter::finish() {
  const size_t limit = limit_;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.stage < b.stage; });
  std::vector<Diagnostic> all = std::move(located_);
  for (Pending& p : pending_) {
    all.push_back(make_error_about(p.code, locator_.locate(p.offset), p.name));
    all.back().notes = locator_.notes(p.offset);
  }
  std::stable_sort(all.begin(), all.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.where.file != b.where.file) return a.where.file < b.where.file;
    if (a.where.line != b.where.line) return a.where.line < b.where.line;
    return a.where.column < b.where.column;
  });
  if (all.size() > limit) {
    Location at = all[limit].where;
    all.resize(limit);
    all.push_back(make_error(Error::TooManyErrors, at));
  }
  return all;
}

}  // namespace uprog::gold
