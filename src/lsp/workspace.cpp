// The workspace a document's features see (workspace.h).
#include "lsp/workspace.h"

#include <algorithm>
#include <filesystem>

#include "dialect/outline.h"
#include "lsp/uri.h"
#include "support/files.h"

namespace uprog::lsp {
namespace {

namespace fs = std::filesystem;

constexpr uintmax_t kMaxIncludedBytes = 1u << 20;  // as PDL's compiler reads them

bool readable_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && fs::file_size(p, ec) <= kMaxIncludedBytes && !ec;
}

// The names `text`'s #include lines give ("scale.h", PUP's lib.puh, PDL's "..\common.h" with
// '/'), found over its words so that a commented-out #include is none.
std::vector<std::string> include_names(const TextDocument& doc) {
  std::vector<std::string> names;
  if (doc.dialect == nullptr) return names;
  for (const dialect::SourceWord& w : dialect::source_words(doc.text, doc.dialect->word_syntax())) {
    if (!w.line_start || w.text != "#include") continue;
    std::string_view rest = dialect::rest_of_line(doc.text, w.offset + w.text.size());
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
    const bool quoted = !rest.empty() && (rest.front() == '"' || rest.front() == '<');
    if (quoted) rest.remove_prefix(1);
    std::string name(rest.substr(0, rest.find_first_of(quoted ? "\">" : " \t\r")));
    for (char& c : name)
      if (c == '\\') c = '/';
    if (!name.empty()) names.push_back(std::move(name));
  }
  return names;
}

}  // namespace

std::string normal_path(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? fs::path(path) : absolute).lexically_normal().string();
}

const TextDocument* Workspace::open_at(const std::string& path) const {
  const std::string wanted = normal_path(path);
  for (const TextDocument* d : open_)
    if (!d->path.empty() && normal_path(d->path) == wanted) return d;
  return nullptr;
}

IncludeSearch Workspace::include_search() const {
  IncludeSearch search;
  search.folders = folders_;
  search.open_text = [this](const std::string& path) -> std::optional<std::string> {
    if (const TextDocument* d = open_at(path)) return d->text;
    return std::nullopt;
  };
  return search;
}

std::optional<std::string> Workspace::find_include(const std::string& includer,
                                                   const std::string& name,
                                                   const std::string& root) const {
  const fs::path given(name);
  std::vector<fs::path> candidates;
  if (given.is_absolute()) {
    candidates.push_back(given);
  } else {
    candidates.push_back(fs::path(includer).parent_path() / given);
    // PUP (whose headers are .puh): a header's #include without a folder is also looked for
    // beside the .pup (pup_source.cpp); PDL's preprocessor looks beside the includer only.
    if (includer != root && given.parent_path().empty() && given.extension() == ".puh")
      candidates.push_back(fs::path(root).parent_path() / given);
    for (const std::string& folder : folders_) candidates.push_back(fs::path(folder) / given);
  }
  for (const fs::path& c : candidates) {
    const std::string path = normal_path(c.string());
    if (open_at(path) != nullptr || readable_file(path)) return path;
  }
  return std::nullopt;
}

std::vector<std::string> Workspace::includes_of(const TextDocument& doc, int depth) const {
  std::vector<std::string> files;
  if (doc.path.empty()) return files;
  std::vector<std::pair<const TextDocument*, int>> pending = {{&doc, 0}};
  while (!pending.empty()) {
    const auto [includer, level] = pending.back();
    pending.pop_back();
    for (const std::string& name : include_names(*includer)) {
      const std::optional<std::string> file = find_include(includer->path, name, doc.path);
      if (!file || *file == normal_path(doc.path) ||
          std::find(files.begin(), files.end(), *file) != files.end())
        continue;
      files.push_back(*file);
      if (level + 1 < depth) {
        if (const TextDocument* inner = load(*file, doc)) pending.emplace_back(inner, level + 1);
      }
    }
  }
  return files;
}

const TextDocument* Workspace::load(const std::string& path, const TextDocument& like) const {
  if (const TextDocument* d = open_at(path)) return d;
  const std::string normal = normal_path(path);
  for (const TextDocument& d : loaded_)
    if (d.path == normal) return &d;
  if (!readable_file(normal)) return nullptr;
  std::optional<std::string> text = read_text_file(normal);
  if (!text) return nullptr;
  TextDocument d;
  d.uri = uri_from_path(normal);
  d.path = normal;
  d.language_id = like.language_id;
  d.dialect = like.dialect;
  d.text = std::move(*text);
  return &loaded_.emplace_back(std::move(d));
}

}  // namespace uprog::lsp
