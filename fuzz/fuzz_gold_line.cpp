// libFuzzer target: the Gold command line (gold::compile_line) on an arbitrary host line, with a
// few known program globals; a line it accepts must encode, load and verify,
// and runs for a bounded budget.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "bytecode/image.h"
#include "dialects/gold/compile.h"
#include "run_image.h"

namespace {

const std::vector<uprog::gold::KnownGlobal>& known() {
  static const std::vector<uprog::gold::KnownGlobal> globals = [] {
    const uprog::gold::CompileResult program = uprog::gold::compile(
        uprog::SourceFile{"p.ehl", "int myvar, arr[3]\nfloat temp, farr[4]\n##A\nmyvar = 1\n"});
    if (!program.ok()) abort();
    return uprog::gold::known_globals(program.image);
  }();
  return globals;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const gold::CompiledLine result = gold::compile_line(line, known());
  if (!result.ok()) return 0;
  const std::vector<uint8_t> bytes = bytecode::encode(result.image);
  const vm::LoadStatus status = fuzz::load_and_run(bytes.data(), bytes.size());
  if (!status.ok() && !status.no_memory) abort();
  return 0;
}
