// The AG300 download (ADownloadUProg[1..3]) and upload (AUploadUProg) as the host writes them:
// what dialect::Dialect::download_lines sends, and the limits the firmware checks.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace uprog::pup {

constexpr size_t kMaxProgramBytes = 262144;
constexpr size_t kMaxChunkBytes = 240;

// [1],n; [2],HEX per chunk of at most 240 bytes; [3],0xCRC (the header's CRC).
std::vector<std::string> download_lines(const std::vector<uint8_t>& cup);

std::string to_hex(const std::string& bytes);
// false when `hex` is not an even number of hex digits.
bool from_hex(const std::string& hex, std::string& out);

}  // namespace uprog::pup
