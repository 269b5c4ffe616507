// libFuzzer target, generated per registered dialect (fuzz_compile_NAME): the input as a source
// of the dialect, compiled in memory. A stored form the compiler accepts must be one its own drive
// takes (a refusal is a compiler bug), and it runs for a bounded while.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_dialect.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const dialect::Dialect& d = fuzz::fuzzed_dialect();
  const SourceFile source{std::string(d.sample_program().file_name),
                          std::string(reinterpret_cast<const char*>(data), size)};
  const dialect::CompileOutput out = d.compile_source(source, {});
  if (!out.ok()) return 0;
  auto drive = fuzz::fresh_drive();
  const controller::DownloadResult r = drive->download(out.stored_form);
  if (!r.ok && !r.storage_failed && out.stored_form.size() <= d.max_download_bytes()) std::abort();
  if (r.ok) {
    (void)drive->start_program({});
    drive->advance(20'000);  // 20 ms of virtual time
  }
  return 0;
}
