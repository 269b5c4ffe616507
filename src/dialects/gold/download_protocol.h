// Downloading a program over the command line (docs/protocol.md, "Download"): the DL lines, their
// limits and error codes, and the host's side that turns an image into those lines.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace uprog::gold {

// Largest image a host may announce: a transfer can never make the drive hold more than this.
constexpr std::size_t kDownloadMaxBytes = 1024 * 1024;
// Bytes per DL= line: "DL=" and two hex digits a byte stay within the 511-character line.
constexpr std::size_t kDownloadChunkBytes = 254;

// The lines a host sends to download `image`: DL##BEGIN=<size>, DL=<hex>..., DL##END.
std::vector<std::string> download_lines(const std::vector<uint8_t>& image);

}  // namespace uprog::gold
