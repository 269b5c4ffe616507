// The download's host side and hex helpers (download.h); the firmware's side is in
// download_receiver.cpp.
#include "dialects/pup/download.h"

#include <fmt/core.h>

#include "dialects/pup/cup_file.h"

namespace uprog::pup {

std::string to_hex(const std::string& bytes) {
  std::string out;
  for (unsigned char c : bytes) out += fmt::format("{:02X}", c);
  return out;
}

std::vector<std::string> download_lines(const std::vector<uint8_t>& cup) {
  const std::string bytes(cup.begin(), cup.end());
  std::vector<std::string> lines = {fmt::format("ADownloadUProg[1],{}", bytes.size())};
  for (size_t at = 0; at < bytes.size(); at += kHostChunkBytes) {
    lines.push_back(std::string(kChunkPrefix) + to_hex(bytes.substr(at, kHostChunkBytes)));
  }
  // The CRC the header's first line declares (0 for `% 000000`, not checked).
  const auto crc = declared_crc(bytes);
  lines.push_back(fmt::format("ADownloadUProg[3],0x{:08X}", crc ? crc->value : 0));
  return lines;
}

}  // namespace uprog::pup
