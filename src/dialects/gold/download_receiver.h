// One host's download in progress: collects the bytes of DL lines up to DL##END, refusing
// anything malformed. Any error drops the transfer; the stored program is untouched until the
// finished image passes Firmware::download().
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "dialect/answer.h"

namespace uprog::gold {

using dialect::Answer;

class DownloadReceiver {
 public:
  // True for the expressions this class handles: DL##... and DL=... (any case, blanks allowed).
  static bool is_download_command(std::string_view expression);

  // Handles one download expression. Returns an error answer, or nullopt for success; when
  // DL##END completes a transfer, `finished` receives the image (still to be verified).
  std::optional<Answer> handle(std::string_view expression, std::vector<uint8_t>& finished);

  bool in_progress() const { return in_progress_; }
  void abort();

 private:
  Answer fail(int32_t code, std::string why);

  bool in_progress_ = false;
  std::size_t announced_ = 0;
  std::vector<uint8_t> bytes_;
};

}  // namespace uprog::gold
