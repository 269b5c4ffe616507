// A dialect's reference (dialect/reference.h) indexed by name for hover, completion and
// signature help: found as written, else ignoring case where the dialect's names do.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/dialect.h"

namespace uprog::lsp {

class ReferenceIndex {
 public:
  explicit ReferenceIndex(const dialect::Dialect& d);
  const dialect::ReferenceEntry* find(std::string_view name) const;
  const std::vector<dialect::ReferenceEntry>& entries() const { return entries_; }

 private:
  std::vector<dialect::ReferenceEntry> entries_;
  std::map<std::string, size_t, std::less<>> exact_, folded_;
  bool ignore_case_;
};

// "**PX** (drive command)", the text, unit, range, access and source, as Markdown.
std::string hover_markdown(const dialect::ReferenceEntry& e);
// "drive command", "keyword", ... for a completion item's detail.
std::string kind_name(dialect::ReferenceKind kind);

}  // namespace uprog::lsp
