// libFuzzer target: the shared preprocessor (src/preproc) on arbitrary source text, with Gold's
// options, then every output offset mapped back through the source map.
#include <cstddef>
#include <cstdint>
#include <string>

#include "preproc/preprocess.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  SourceFile source{"fuzz.ehl", std::string(reinterpret_cast<const char*>(data), size)};
  DiagnosticList diagnostics;
  preproc::PreprocOptions options;
  // The first byte picks the C-like variant too, so both paths of each switch are explored.
  if (size > 0 && (data[0] & 1)) {
    options.undefined_identifier_is_zero = true;
    options.unknown_hash_lines_pass_through = false;
    options.allow_function_macros = true;
  }
  const preproc::Preprocessed out = preproc::preprocess(source, options, diagnostics);
  for (size_t i = 0; i <= out.text.size(); i += 1 + out.text.size() / 64) {
    const Location at = out.map.locate(i);
    (void)at;
    (void)out.map.expansion_at(i);
  }
  return 0;
}
