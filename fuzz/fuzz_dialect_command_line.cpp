// libFuzzer target, generated per registered dialect (fuzz_command_line_NAME): each input line
// sent by a host to a drive of the dialect running its sample program, then 20 ms of virtual time
// so that whatever the lines started runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_dialect.h"
#include "host_lines.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto drive = uprog::fuzz::drive_with_sample();
  auto host = drive->open_session();
  uprog::fuzz::send_lines_then_run(*drive,
                                   std::string_view(reinterpret_cast<const char*>(data), size),
                                   [&](std::string_view line) { return host->send(line); });
  return 0;
}
