// libFuzzer target: host lines into the AG300 command line (the message interpreter), with a
// program stored whose tasks, function, event and waits the lines can reach; then 20 ms.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "controller/controller.h"
#include "dialects/pup/dialect.h"
#include "dialects/pup/pup_compiler.h"
#include "host_lines.h"

namespace {

constexpr const char* kProgram =
    "#event 6 1\n#information fuzz\nAProgTask[1]\nwhile (1)\nAGenData[2] = AGenData[2] + 1\n"
    "AWaitTime, 1\nend\nAProgTask[2]\nAWaitStatus[3], 2\nAProgFuncCall, 1\nAProgHalt[2]\n"
    "AProgFunc[1]\nAGenData[1] = AGenData[1] * 3 / (AGenData[2] + 1)\nreturn\n";

const std::vector<uint8_t>& program_cup() {
  static const std::vector<uint8_t> bytes = [] {
    const uprog::pup::PupOutput r = uprog::pup::compile_pup("fuzz.pup", kProgram, 0);
    if (!r.ok()) abort();
    const std::string cup = uprog::pup::write_cup(r.program);
    return std::vector<uint8_t>(cup.begin(), cup.end());
  }();
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  controller::ControllerOptions options;
  options.dialect = &pup::dialect();
  controller::Controller drive(options);
  if (!drive.download(program_cup()).ok) abort();
  fuzz::send_lines_then_run(drive, std::string_view(reinterpret_cast<const char*>(data), size),
                            [&](std::string_view line) { return drive.send(line); });
  return 0;
}
