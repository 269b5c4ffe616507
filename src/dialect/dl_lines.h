// The DL download lines Gold and PDL drives take (docs/protocol.md, "Download"): DL##BEGIN=<bytes>,
// DL=<hex>, DL##END, DL##ABORT; their limits and error codes, the host's side that turns an image
// into those lines, and the drive's side over the shared transfer (download_receiver.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/download_receiver.h"

namespace uprog::dialect {

// Largest image a host may announce: a transfer can never make the drive hold more than this.
constexpr std::size_t kDownloadMaxBytes = 1024 * 1024;
// Bytes per DL= line: "DL=" and two hex digits a byte stay within the 511-character line.
constexpr std::size_t kDownloadChunkBytes = 254;

// The error codes of the DL lines (Gold's interpreter codes, which PDL drives answer too).
constexpr int32_t kDlSyntax = 19;         // not one of the four DL lines ("Command syntax error")
constexpr int32_t kDlStorage = 206;       // the finished image could not be stored
constexpr int32_t kDlNoDownload = 210;    // DL= or DL##END without a DL##BEGIN on this connection
constexpr int32_t kDlBadSize = 211;       // a bad size in DL##BEGIN, or DL##END before all bytes
constexpr int32_t kDlBadChunk = 212;      // a DL= line that is not hex pairs, or too many bytes
constexpr int32_t kDlImageRefused = 213;  // the image failed its CRC, format or the verifier

// The lines a host sends to download `image`: DL##BEGIN=<size>, DL=<hex>..., DL##END.
std::vector<std::string> download_lines(const std::vector<uint8_t>& image);

// One connection's DL lines on the drive's side.
class DlReceiver {
 public:
  DlReceiver();
  // True for the lines this class handles: DL##... and DL=... (any case, blanks allowed).
  static bool is_download_command(std::string_view expression);
  // Handles one DL line. Returns an error answer, or nullopt for success; when DL##END completes
  // a transfer, `finished` receives the image (still to be verified).
  std::optional<Answer> handle(std::string_view expression, std::vector<uint8_t>& finished);
  bool in_progress() const { return transfer_.in_progress(); }
  void abort() { transfer_.abort(); }

 private:
  DownloadReceiver transfer_;
};

}  // namespace uprog::dialect
