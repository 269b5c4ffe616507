// libFuzzer target: the ST compiler (preprocessor, lexer, parser, checks, code generator) on an
// arbitrary source; a program it accepts must encode, load and verify, and then runs on an S300
// drive (stored, PLCRUN, 20 ms of its cyclic tasks).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "controller/controller.h"
#include "dialects/st/compile.h"
#include "dialects/st/dialect.h"
#include "run_image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const st::CompileResult result = st::compile(SourceFile{"fuzz.st", text});
  if (!result.ok()) return 0;
  // What the compiler produces, the drive must take: a compiler bug shows as a crash here.
  const std::vector<uint8_t> bytes = bytecode::encode(result.image);
  const vm::LoadStatus status = fuzz::load_and_run(bytes.data(), bytes.size());
  if (!status.ok() && !status.no_memory) abort();
  controller::ControllerOptions options;
  options.dialect = &st::dialect();
  controller::Controller drive(options);
  if (!drive.download(std::vector<uint8_t>(text.begin(), text.end())).ok) abort();
  for (const auto& a : drive.query("PLCRUN"))
    if (a.is_error()) abort();  // it compiled here, so it compiles on the drive
  drive.advance(20'000);
  (void)drive.take_log();
  (void)drive.take_output();
  return 0;
}
