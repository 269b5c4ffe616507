// Reading whole files and writing them atomically (write a temporary, fsync, rename, fsync the
// directory), so that a kill at any moment leaves the old file or the new one, never a mix.
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
// Returns false with `error` set when the file could not be replaced; the old one is intact.
bool write_file_atomically(const std::string& path, const void* data, size_t size,
                           std::string* error = nullptr);

}  // namespace uprog
