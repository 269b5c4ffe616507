// Reference look-up and its hover text (reference_index.h).
#include "lsp/reference_index.h"

#include <cctype>

namespace uprog::lsp {
namespace {

std::string folded(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

ReferenceIndex::ReferenceIndex(const dialect::Dialect& d)
    : entries_(d.reference()), ignore_case_(d.names_ignore_case()) {
  for (size_t i = 0; i < entries_.size(); ++i) {
    exact_.emplace(entries_[i].name, i);  // the first of a name stays
    folded_.emplace(folded(entries_[i].name), i);
  }
}

const dialect::ReferenceEntry* ReferenceIndex::find(std::string_view name) const {
  if (const auto it = exact_.find(name); it != exact_.end()) return &entries_[it->second];
  if (!ignore_case_) return nullptr;
  const auto it = folded_.find(folded(name));
  return it == folded_.end() ? nullptr : &entries_[it->second];
}

std::string kind_name(dialect::ReferenceKind kind) {
  switch (kind) {
    case dialect::ReferenceKind::Command:
      return "drive command";
    case dialect::ReferenceKind::SystemVariable:
      return "system variable";
    case dialect::ReferenceKind::Function:
      return "built-in function";
    case dialect::ReferenceKind::Keyword:
      return "keyword";
    case dialect::ReferenceKind::Directive:
      return "directive";
    case dialect::ReferenceKind::Constant:
      return "constant";
  }
  return "";
}

std::string hover_markdown(const dialect::ReferenceEntry& e) {
  std::string md = "**" + (e.signature.empty() ? e.name : e.signature) + "** (" +
                   kind_name(e.kind) + ")\n\n" + e.summary + "\n";
  if (!e.unit.empty()) md += "\n- unit: " + e.unit;
  if (!e.range.empty()) md += "\n- range: " + e.range;
  if (!e.access.empty()) md += "\n- access: " + e.access;
  md += "\n\n*Source: " + e.source + "*";
  return md;
}

}  // namespace uprog::lsp
