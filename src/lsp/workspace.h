// The files a document's features look beyond it at: the workspace's folders (initialize's
// rootUri and workspaceFolders, didChangeWorkspaceFolders), the other open documents, and the
// files an #include names, found as the compilers find them (beside the includer, then in each
// workspace folder), an open document's unsaved text standing for its file's.
#pragma once
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "lsp/text_document.h"
#include "support/include_search.h"

namespace uprog::lsp {

// How deep the features follow #include (PDL's compiler: 20 files).
constexpr int kIncludeDepth = 20;

// An absolute, lexically normal path: how the workspace compares files.
std::string normal_path(const std::string& path);

class Workspace {
 public:
  Workspace(std::vector<std::string> folders, std::vector<const TextDocument*> open)
      : folders_(std::move(folders)), open_(std::move(open)) {}

  const std::vector<const TextDocument*>& open() const { return open_; }
  // The open document of the file at `path`; nullptr when it is not open.
  const TextDocument* open_at(const std::string& path) const;
  // For the compilers: the workspace's folders, and the open documents' texts.
  IncludeSearch include_search() const;

  // The files `doc`'s #include lines name, as its compiler finds them (normal paths), and those
  // they include in turn (at most `depth` deep); none for a document without a path.
  std::vector<std::string> includes_of(const TextDocument& doc, int depth = 1) const;
  // The file at `path` as a document in `doc`'s dialect: the open one, else the disk's (at most
  // 1 MiB), kept in this workspace as long as it lives; nullptr when it cannot be read.
  const TextDocument* load(const std::string& path, const TextDocument& like) const;

 private:
  // Where `includer`'s `#include name` is found, for the document at `root` (a normal path).
  std::optional<std::string> find_include(const std::string& includer, const std::string& name,
                                          const std::string& root) const;

  std::vector<std::string> folders_;
  std::vector<const TextDocument*> open_;
  mutable std::deque<TextDocument> loaded_;  // files read from disk for this request
};

}  // namespace uprog::lsp
