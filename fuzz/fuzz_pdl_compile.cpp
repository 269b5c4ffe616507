// libFuzzer target: the PDL compiler (preprocessor, tokenizer, one-pass compiler) on an arbitrary
// source file; an image it accepts must encode, load and verify, and runs for a bounded budget.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "dialects/pdl/compile.h"
#include "run_image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  const SourceFile source{"fuzz.pdl", std::string(reinterpret_cast<const char*>(data), size)};
  pdl::CompileOptions options;
  options.read_includes = false;  // #include paths in the input must not read the machine's files
  const pdl::CompileResult result = pdl::compile(source, options);
  if (!result.ok()) return 0;
  // What the compiler produces, the drive must take: a compiler bug shows as a crash here.
  const std::vector<uint8_t> bytes = bytecode::encode(result.image);
  const vm::LoadStatus status = fuzz::load_and_run(bytes.data(), bytes.size());
  if (!status.ok() && !status.no_memory) abort();
  return 0;
}
