// libFuzzer target, generated per registered dialect (fuzz_download_NAME): the input as a stored
// form given to a drive of the dialect that holds its sample program. A refused form must leave
// the sample stored (it still runs after a power cycle); an accepted one runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "fuzz_dialect.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  auto drive = fuzz::drive_with_sample();
  const std::vector<uint8_t> form(data, data + size);
  const controller::DownloadResult r = drive->download(form);
  if (!r.ok) {
    if (r.error.empty()) std::abort();  // a refusal says why
    drive->reboot();
    if (drive->start_program(fuzz::fuzzed_dialect().sample_program().entry) != "") std::abort();
  } else {
    (void)drive->start_program({});
  }
  drive->advance(20'000);
  (void)drive->take_log();
  return 0;
}
