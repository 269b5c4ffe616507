// libFuzzer target: the transcript parser and runner (`uprog transcript`) on arbitrary text.
// `load` paths resolve in examples/gold. Inputs that ask for more than 2 s of virtual time in
// one `wait` are skipped: a long wait is a long simulation, not a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "transcript/transcript.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string directive, duration;
    words >> directive >> duration;
    uint64_t us = 0;
    if (directive == "wait" && transcript::parse_duration_us(duration, us) && us > 2'000'000)
      return 0;
  }
  (void)transcript::run_transcript_text(text, "fuzz.txt", UPROG_FUZZ_EXAMPLES_DIR);
  return 0;
}
