// `uprog build FILE -o OUT`: compiles a Gold source into a binary image (.upi), or with
// --emit asm into its uprog assembly text.
#include <fmt/core.h>

#include <memory>
#include <string>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "commands.h"
#include "huge_heap.h"
#include "dialects/gold/compile.h"
#include "support/files.h"

namespace uprog::cli {
namespace {

void add_build(CLI::App* cmd, Action& action) {
  auto input = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto emit = std::make_shared<std::string>("image");
  cmd->add_option("FILE", *input, "Gold source file")->required();
  cmd->add_option("-o,--output", *output, "output file (default FILE.upi, or FILE.s with --emit asm)");
  cmd->add_option("--emit", *emit, "image or asm")->check(CLI::IsMember({"image", "asm"}));
  cmd->callback([&action, input, output, emit] {
    action = [input, output, emit] {
      prepare_heap_for_compiling({*input});
      const gold::CompileResult r = gold::compile_file(*input);
      if (!r.diagnostics.empty()) fmt::print(stderr, "{}", format_text(r.diagnostics));
      if (!r.ok()) return 1;
      std::string error;
      bool written = false;
      if (*emit == "asm") {
        const std::string text = bytecode::disassemble(r.image);
        const std::string out = output->empty() ? *input + ".s" : *output;
        written = write_file_atomically(out, text.data(), text.size(), &error);
      } else {
        const auto bytes = bytecode::encode(r.image);
        const std::string out = output->empty() ? *input + ".upi" : *output;
        written = write_file_atomically(out, bytes.data(), bytes.size(), &error);
      }
      if (!written) {
        fmt::print(stderr, "uprog build: {}\n", error);
        return 1;
      }
      return 0;
    };
  });
}

const Subcommand kBuild("build", "Compile a Gold source into an image", add_build);

}  // namespace
}  // namespace uprog::cli
