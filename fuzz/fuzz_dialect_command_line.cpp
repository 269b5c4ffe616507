// libFuzzer target, generated per registered dialect (fuzz_command_line_NAME): each input line
// sent by a host to a drive of the dialect running its sample program, then 20 ms of virtual time
// so that whatever the lines started runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_dialect.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto drive = uprog::fuzz::drive_with_sample();
  auto host = drive->open_session();
  std::string_view input(reinterpret_cast<const char*>(data), size);
  while (!input.empty()) {
    const size_t end = input.find('\n');
    (void)host->send(input.substr(0, end));
    if (end == std::string_view::npos) break;
    input.remove_prefix(end + 1);
  }
  drive->advance(20'000);
  (void)drive->take_log();
  (void)drive->take_output();
  return 0;
}
