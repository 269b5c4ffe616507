// The host's side of a download: an image as DL lines (download_protocol.h).
#include "dialects/gold/download_protocol.h"

namespace uprog::gold {

std::vector<std::string> download_lines(const std::vector<uint8_t>& image) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::vector<std::string> lines;
  lines.push_back("DL##BEGIN=" + std::to_string(image.size()));
  for (std::size_t at = 0; at < image.size(); at += kDownloadChunkBytes) {
    const std::size_t end = std::min(image.size(), at + kDownloadChunkBytes);
    std::string line = "DL=";
    for (std::size_t i = at; i < end; ++i) {
      line.push_back(kHex[image[i] >> 4]);
      line.push_back(kHex[image[i] & 0xF]);
    }
    lines.push_back(std::move(line));
  }
  lines.push_back("DL##END");
  return lines;
}

}  // namespace uprog::gold
