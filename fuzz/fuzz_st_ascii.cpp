// libFuzzer target: host lines into an S300 drive's ASCII interface (a session's send, PLCDL
// included), with a PLC program running whose globals, DPRVARs and PRINTF are reachable; then
// a little virtual time so that whatever the lines started runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "controller/controller.h"
#include "dialects/st/dialect.h"
#include "host_lines.h"

namespace {

constexpr std::string_view kProgram =
    "LONG A, B; DLONG D; WORD W;\n"
    "PROGRAM PLC1\n  A := A + 1;\n  LIMITW(B, A, DPRVAR1);\nEND_PROGRAM\n"
    "PROGRAM PLCMAIN\n  IF A MOD 100 = 0 THEN\n    PRINTF('a=%d\\n', A);\n  END_IF;\n"
    "  XREAD('PFB', B);\n  ADDDLONG(D, D, A);\nEND_PROGRAM\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  controller::ControllerOptions options;
  options.dialect = &st::dialect();
  controller::Controller drive(options);
  if (!drive.download(std::vector<uint8_t>(kProgram.begin(), kProgram.end())).ok) abort();
  for (const auto& a : drive.query("PLCRUN"))
    if (a.is_error()) abort();
  std::unique_ptr<dialect::Session> host = drive.open_session();
  fuzz::send_lines_then_run(drive, std::string_view(reinterpret_cast<const char*>(data), size),
                            [&](std::string_view line) { return host->send(line); });
  return 0;
}
