// One host's download in progress, whatever the dialect's syntax: a size is announced, the bytes
// come as hex-digit pairs, then the end. Each dialect parses its own lines (DL##BEGIN=n, PLCDL
// BEGIN n, ADownloadUProg[1],n …) and hands the parts here; a fault answers with the dialect's
// code and drops the transfer, and the stored program is untouched until the finished bytes pass
// the firmware's own checks.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/answer.h"

namespace uprog::dialect {

// A fault's code and, where the dialect's table fixes it, its text (else a description).
struct DownloadFaultAnswer {
  int32_t code = 0;
  const char* text = nullptr;
};
// What a dialect answers for each fault of a transfer.
struct DownloadCodes {
  DownloadFaultAnswer not_begun;  // bytes or the end with no transfer begun
  DownloadFaultAnswer bad_size;   // an announced size that is no number or out of range
  DownloadFaultAnswer bad_data;   // bytes that are not hex-digit pairs, or too many in one line
  DownloadFaultAnswer too_many;   // more bytes than announced
  DownloadFaultAnswer too_few;    // the end before all announced bytes came
};

// Decodes hex-digit pairs (either case) onto `out`; false, and `out` as it was, when `hex` is not
// an even number of hex digits.
bool append_hex_bytes(std::string_view hex, std::vector<uint8_t>& out);

class DownloadReceiver {
 public:
  // `max_bytes`: the largest size a host may announce. `max_line_bytes`: bytes one line may bring.
  DownloadReceiver(std::size_t max_bytes, DownloadCodes codes,
                   std::size_t max_line_bytes = SIZE_MAX);

  // Starts afresh (a transfer in progress is dropped: a host that lost its place can retry).
  std::optional<Answer> begin(std::string_view decimal_size);
  std::optional<Answer> begin(std::size_t size);
  std::optional<Answer> add_hex(std::string_view hex);
  // When every announced byte came, moves them into `finished`.
  std::optional<Answer> finish(std::vector<uint8_t>& finished);
  void abort();

  bool in_progress() const { return in_progress_; }
  std::size_t max_bytes() const { return max_bytes_; }

 private:
  Answer fail(DownloadFaultAnswer answer, std::string description);

  std::size_t max_bytes_;
  DownloadCodes codes_;
  std::size_t max_line_bytes_;
  bool in_progress_ = false;
  std::size_t announced_ = 0;
  std::vector<uint8_t> bytes_;
};

}  // namespace uprog::dialect
