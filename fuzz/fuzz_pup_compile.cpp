// libFuzzer target: PUP source into the PUP compiler. An accepted program's CUP must read back
// strictly (its own header) and, where the loader takes it, its image must pass the verifier:
// the loader's per-line checks promise what the verifier proves.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "bytecode/image_view.h"
#include "bytecode/verifier.h"
#include "dialects/pup/cup_loader.h"
#include "dialects/pup/pup_compiler.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  if (size > 1 << 16) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const pup::PupOutput out = pup::compile_pup("fuzz.pup", text, 0);
  if (!out.ok()) return 0;
  const std::string cup = pup::write_cup(out.program);
  pup::CupReadError read_error;
  const auto back = pup::read_cup(cup, &read_error);
  if (!back || back->lines != out.program.lines) abort();
  std::string why;
  const auto loaded = pup::load_cup(*back, &why);
  if (!loaded) return 0;
  const std::vector<uint8_t> bytes = bytecode::encode(loaded->image);
  bytecode::ImageView view;
  if (bytecode::load_image(bytes.data(), bytes.size(), view) != bytecode::LoadError::Ok) abort();
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(view) / 4 + 1);
  if (!bytecode::verify(view, bytecode::VerifyLimits{}, scratch.data(), scratch.size() * 4).ok())
    abort();
  return 0;
}
