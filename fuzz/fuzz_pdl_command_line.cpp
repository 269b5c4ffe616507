// libFuzzer target: host lines into a PDL drive (its Session: reads, writes, lists, run/kill,
// level, reset, DL lines) with a program stored and its tasks running; then a little virtual
// time so that what the lines started runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "bytecode/image.h"
#include "controller/controller.h"
#include "dialects/pdl/compile.h"
#include "dialects/pdl/dialect.h"
#include "host_lines.h"

namespace {

constexpr const char* kProgram =
    "#long counter, arr[4], *p\n#short sh\n#float fl\n#long _ro fixed\n#long _lp(2,3) guarded\n"
    "proc bump(long by, long * where) do\n  *where = *where + by;\nend;\n"
    "#task/1;\nloop (0) do\n  counter++;\n  bump(2, &arr[1]);\nend;\n"
    "_run:\n  printl/103(\"c=%d f=%g \", counter, fl);\n  p = &arr;\n  *p[sh] = 5;\n  "
    "retprintl(\"done\");\n"
    "_spin:\n  sleep 1;\n  goto _spin;\n";

const std::vector<uint8_t>& program_image() {
  static const std::vector<uint8_t> bytes = [] {
    const uprog::pdl::CompileResult r =
        uprog::pdl::compile(uprog::SourceFile{"fuzz.pdl", kProgram});
    if (!r.ok()) abort();
    return uprog::bytecode::encode(r.image);
  }();
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  controller::ControllerOptions options;
  options.dialect = &pdl::dialect();
  controller::Controller drive(options);
  if (!drive.download(program_image()).ok) abort();
  (void)drive.query("reset");
  auto host = drive.open_session();
  fuzz::send_lines_then_run(drive, std::string_view(reinterpret_cast<const char*>(data), size),
                            [&](std::string_view line) { return host->send(line); });
  return 0;
}
