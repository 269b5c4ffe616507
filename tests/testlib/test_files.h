// Test support: the data files of a test folder, and reading one whole.
#pragma once
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace uprog::test {

// The files under UPROG_SOURCE_DIR/dir ending in `extension` ("" for all), sorted.
inline std::vector<std::filesystem::path> source_files(const std::string& dir,
                                                       const std::string& extension = "") {
  std::vector<std::filesystem::path> files;
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(UPROG_SOURCE_DIR) / dir))
    if (extension.empty() || e.path().extension() == extension) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

inline std::string read_whole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace uprog::test
