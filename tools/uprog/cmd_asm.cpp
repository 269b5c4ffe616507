// `uprog asm FILE -o FILE.upi` and `uprog disasm FILE.upi`: the two forms of an image.
#include <fmt/core.h>

#include <cstdio>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "commands.h"
#include "support/files.h"

namespace uprog::cli {

namespace {

void add_asm(Options& cmd, Action& action) {
  auto input = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  cmd.option("FILE", *input, "assembly source").required();
  cmd.option("-o,--output", *output, "image to write (default: FILE with .upi)");
  cmd.on_chosen([&action, input, output] {
    action = [input, output] {
      std::string error;
      auto text = read_text_file(*input, &error);
      if (!text) {
        fmt::print(stderr, "uprog asm: {}\n", error);
        return 1;
      }
      bytecode::Image image;
      std::vector<Diagnostic> errors;
      if (!bytecode::assemble(*text, *input, image, errors)) {
        fmt::print(stderr, "{}", format_text(errors));
        return 1;
      }
      const std::string out = output->empty() ? *input + ".upi" : *output;
      const auto bytes = bytecode::encode(image);
      if (!write_file_atomically(out, bytes.data(), bytes.size(), &error)) {
        fmt::print(stderr, "uprog asm: {}\n", error);
        return 1;
      }
      return 0;
    };
  });
}

void add_disasm(Options& cmd, Action& action) {
  auto input = std::make_shared<std::string>();
  cmd.option("FILE", *input, "binary image (.upi)").required();
  cmd.on_chosen([&action, input] {
    action = [input] {
      std::string error;
      auto bytes = read_binary_file(*input, &error);
      bytecode::Image image;
      if (!bytes || !bytecode::decode(bytes->data(), bytes->size(), image, error)) {
        fmt::print(stderr, "uprog disasm: {}: {}\n", *input, error);
        return 1;
      }
      fmt::print("{}", bytecode::disassemble(image));
      return 0;
    };
  });
}

const Subcommand kAsm("asm", "Assemble uprog assembly into a binary image", add_asm);
const Subcommand kDisasm("disasm", "Print a binary image as uprog assembly", add_disasm);

}  // namespace
}  // namespace uprog::cli
