// libFuzzer target: host lines into a Controller's command line (Controller::send), with a
// stored program loaded so that its globals, XQ and auto-routines are reachable; then a little
// virtual time so that whatever the lines started runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "bytecode/image.h"
#include "controller/controller.h"
#include "dialects/gold/compile.h"
#include "dialects/gold/dialect.h"
#include "host_lines.h"

namespace {

constexpr const char* kProgram =
    "int myvar, arr[3]\nfloat temp, farr[4]\n"
    "function [int r] = twice(int x)\nr = 2 * x\nreturn\n"
    "##A\nmyvar = twice(myvar) + 1\ntemp = temp + 0.5\nexit\n"
    "##AUTO_I1\narr[1] = arr[1] + 1\nreturn\n";

const std::vector<uint8_t>& program_image() {
  static const std::vector<uint8_t> bytes = [] {
    const uprog::gold::CompileResult r =
        uprog::gold::compile(uprog::SourceFile{"fuzz.ehl", kProgram});
    if (!r.ok()) abort();
    return uprog::bytecode::encode(r.image);
  }();
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  controller::ControllerOptions options;
  options.dialect = &gold::dialect();
  controller::Controller drive(options);
  if (!drive.download(program_image()).ok || !drive.query("CC").empty()) abort();
  fuzz::send_lines_then_run(drive, std::string_view(reinterpret_cast<const char*>(data), size),
                            [&](std::string_view line) { return drive.send(line); });
  return 0;
}
