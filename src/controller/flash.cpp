// Flash records as files or in memory (flash.h).
#include "controller/flash.h"

#include <filesystem>

#include "support/files.h"

namespace uprog::controller {

StateFlash::StateFlash(std::string state_dir) : dir_(std::move(state_dir)) {
  if (dir_.empty()) return;
  std::error_code ignored;  // a directory that cannot be made shows up as a failing read or write
  std::filesystem::create_directories(dir_, ignored);
  // What a kill during an earlier write left (a power loss on a real drive): never kept.
  remove_stale_temporaries(dir_);
}

std::optional<std::vector<uint8_t>> StateFlash::read(std::string_view name, std::string* error) {
  if (error) error->clear();
  if (dir_.empty()) {
    const auto it = memory_.find(name);
    if (it == memory_.end()) return std::nullopt;
    return it->second;
  }
  const std::string path = where(name);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  return read_binary_file(path, error);
}

bool StateFlash::write(std::string_view name, std::span<const uint8_t> bytes, std::string* error) {
  if (dir_.empty()) {
    memory_[std::string(name)].assign(bytes.begin(), bytes.end());
    return true;
  }
  return write_file_atomically(where(name), bytes.data(), bytes.size(), error);
}

std::string StateFlash::where(std::string_view name) const {
  return dir_.empty() ? std::string(name) + " (in memory)" : dir_ + "/" + std::string(name);
}

}  // namespace uprog::controller
