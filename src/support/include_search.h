// Where a compiler that reads #include'd files (PDL, PUP) looks besides the includer's own
// folder, and the text an editor holds open, unsaved, in place of a file's (`uprog lsp`). The
// default (no folders, no open texts) is the command line's: the disk, beside the includer.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace uprog {

struct IncludeSearch {
  // Searched in order for a relative name not found beside its includer (the workspace's
  // folders).
  std::vector<std::string> folders;
  // The text of the file at `path` as an editor holds it; nullopt: the disk's. Null: the disk.
  std::function<std::optional<std::string>(const std::string& path)> open_text;

  // Reads `path`: the open text when there is one, else `read_disk(path, why)`.
  template <class ReadDisk>
  std::optional<std::string> read(const std::string& path, std::string* why,
                                  const ReadDisk& read_disk) const {
    if (open_text) {
      if (std::optional<std::string> text = open_text(path)) return text;
    }
    return read_disk(path, why);
  }
};

}  // namespace uprog
