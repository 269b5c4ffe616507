// The AG300 download (ADownloadUProg[1..3]) and upload (AUploadUProg) as the host writes them:
// what dialect::Dialect::download_lines sends, and the limits the firmware checks.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/download_receiver.h"
#include "dialect/line_framer.h"
#include "dialects/pup/cup_file.h"

namespace uprog::pup {

constexpr size_t kMaxChunkBytes = 240;  // what one ADownloadUProg[2] may bring (the spec)
// The transfer's faults as the spec's AG300 error table answers them.
constexpr dialect::DownloadCodes kCupDownloadCodes{
    .not_begun = {40, "download not begun"},
    .bad_size = {41, "length"},
    .bad_data = {42, "data"},
    .too_many = {41, "length"},
    .too_few = {41, "length"},
};
// What the host sends in one: "ADownloadUProg[2],HEX" within the framer's line (255 characters,
// the firmware's FramerOptions), so 118 bytes; the 240 of a chunk would be a line of 498.
constexpr std::string_view kChunkPrefix = "ADownloadUProg[2],";
constexpr size_t kHostChunkBytes =
    (dialect::FramerOptions{}.max_line_length - kChunkPrefix.size()) / 2;
static_assert(kHostChunkBytes > 0 && kHostChunkBytes <= kMaxChunkBytes);

// [1],n; [2],HEX per chunk of at most kHostChunkBytes; [3],0xCRC (the header's CRC).
std::vector<std::string> download_lines(const std::vector<uint8_t>& cup);

std::string to_hex(const std::string& bytes);

}  // namespace uprog::pup
