// libFuzzer target: drive::read_recording_csv on arbitrary bytes (what `uprog plot`, `--expect`
// and a transcript's `expect` read). An accepted file writes out in the canonical form, which
// reads back to the same recording and writes the same bytes again.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "drive/recording_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string error;
  const std::optional<uprog::drive::Recording> r = uprog::drive::read_recording_csv(text, &error);
  if (!r) {
    if (error.rfind("line ", 0) != 0) std::abort();  // every refusal names its line
    return 0;
  }
  const std::string first = uprog::drive::write_recording_csv(*r);
  const std::optional<uprog::drive::Recording> again =
      uprog::drive::read_recording_csv(first, &error);
  if (!again || uprog::drive::write_recording_csv(*again) != first) std::abort();
  return 0;
}
