// Every stored program holds base instructions only (format 6, bytecode/format.h): each example
// under examples/ and each workload of bench/peers and bench/holdout, compiled by the dialect its
// extension names, has no opcode outside the base set in its image's code; for PUP, whose stored
// form is CUP text, in the code its CUP loader makes of it on the drive. The VM's fused
// instructions are formed at load (vm/fused.def) and never stored.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "bytecode/image_view.h"
#include "bytecode/opcodes.h"
#include "dialects/pup/cup_file.h"
#include "dialects/pup/cup_loader.h"
#include "dialects/registry.h"
#include "testlib/test_files.h"

namespace uprog::test {
namespace {

namespace fs = std::filesystem;

// The first instruction of `code` that is no base instruction, or "" when there is none.
std::string first_not_base(std::span<const uint32_t> code) {
  for (size_t pc = 0; pc < code.size(); pc += bytecode::op_length(bytecode::word_op(code[pc]))) {
    if ((code[pc] & 0xFFu) >= bytecode::kBaseOpCount)
      return "opcode " + std::to_string(code[pc] & 0xFFu) + " at " + std::to_string(pc);
  }
  return "";
}

// The code of the image a drive of `d` loads `out`'s stored form into: the compiler's image
// where it gives it (Gold, PDL, ST: the stored form is that image, or carries it), else what
// PUP's CUP loader makes of the CUP text.
std::vector<uint32_t> stored_code(const dialect::Dialect& d, const dialect::CompileOutput& out,
                                  const fs::path& source) {
  if (out.image) return out.image->code;
  const std::vector<uint8_t>& stored = out.stored_form;
  if (d.name() == "pup") {
    std::string why;
    const auto cup = pup::load_cup(
        pup::read_cup_text(std::string(stored.begin(), stored.end()), source.stem().string()),
        &why);
    EXPECT_TRUE(cup.has_value()) << source << ": " << why;
    return cup ? cup->image.code : std::vector<uint32_t>{};
  }
  bytecode::ImageView view;
  EXPECT_EQ(bytecode::load_image(stored.data(), stored.size(), view), bytecode::LoadError::Ok)
      << source;
  std::vector<uint32_t> code;
  for (uint32_t i = 0; i < view.code.size(); ++i) code.push_back(view.code[i]);
  return code;
}

TEST(BaseOnly, EveryExampleAndWorkloadIsStoredInBaseInstructions) {
  std::vector<fs::path> files;
  for (const char* dir : {"examples/gold", "examples/pdl", "examples/pup", "examples/st",
                          "bench/peers", "bench/holdout"})
    for (const fs::path& f : source_files(dir)) files.push_back(f);
  int compiled = 0;
  for (const fs::path& f : files) {
    const dialect::Dialect* d = dialects::for_file(f.string());
    if (d == nullptr) continue;  // a transcript, a Lua peer, a script
    const dialect::CompileOutput out = d->compile_source(SourceFile{f.string(), read_whole(f)}, {});
    ASSERT_TRUE(out.ok()) << f;
    const std::vector<uint32_t> code = stored_code(*d, out, f);
    EXPECT_FALSE(code.empty()) << f;
    EXPECT_EQ(first_not_base(code), "") << f;
    ++compiled;
  }
  EXPECT_EQ(compiled, 69);  // 35 examples, 14 workloads and 20 held out: every folder was found
}

}  // namespace
}  // namespace uprog::test
