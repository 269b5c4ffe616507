// Reading whole files and writing them atomically (write a nameless temporary, fsync, name it,
// rename, fsync the directory), so that a kill at any moment leaves the old file or the new one,
// never a mix, and no temporary behind.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace uprog {

// nullopt when the file cannot be read; `error` then says why.
std::optional<std::string> read_text_file(const std::string& path, std::string* error = nullptr);
std::optional<std::vector<uint8_t>> read_binary_file(const std::string& path,
                                                     std::string* error = nullptr);
// Removes the temporaries write_file_atomically() left in `dir` when its process was killed
// (NAME.tmp.PID of a process that no longer runs); the number removed. A drive's flash calls it
// at start-up, so that power losses never fill it.
int remove_stale_temporaries(const std::string& dir);
// Returns false with `error` set when the file could not be replaced; the old one is intact.
bool write_file_atomically(const std::string& path, const void* data, size_t size,
                           std::string* error = nullptr);
// Removes the temporaries write_file_atomically() left in `dir` when its process was killed
// (NAME.tmp.PID of a process that no longer runs); the number removed. A drive's flash calls it
// at start-up, so that power losses never fill it.
int remove_stale_temporaries(const std::string& dir);

}  // namespace uprog
