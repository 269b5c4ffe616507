// `uprog build FILE -o OUT`: compiles a source in its dialect into the stored form the drive
// keeps (Gold: a binary image, .upi), or with --emit asm into the image's uprog assembly text.
#include <fmt/core.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>

#include "bytecode/assembly.h"
#include "bytecode/image_view.h"
#include "commands.h"
#include "dialect_choice.h"
#include "huge_heap.h"
#include "support/files.h"
#include "vm/fused.h"
#include "vm/quicken.h"

namespace uprog::cli {
namespace {

struct BuildOptions {
  std::string input;
  std::string output;
  std::string emit = "image";
  std::string dialect;
  bool quickened = false;
};

// For each code word where the VM forms a fused instruction when it loads `image`
// (vm/quicken.h), "quickened: NAME"; "" elsewhere.
std::vector<std::string> quickened_notes(const bytecode::Image& image) {
  const std::vector<uint8_t> bytes = bytecode::encode(image);
  bytecode::ImageView view;
  std::vector<std::string> notes(image.code.size());
  if (bytecode::load_image(bytes.data(), bytes.size(), view) != bytecode::LoadError::Ok)
    return notes;
  std::vector<uint32_t> code = image.code;
  const auto size = static_cast<uint32_t>(code.size());
  std::vector<uint32_t> scratch(vm::quicken_scratch_words(size));
  vm::quicken(code.data(), size, view, scratch.data());
  for (uint32_t pc = 0; pc < size; pc += vm::instruction_length(code[pc]))
    if (vm::is_fused(code[pc]))
      notes[pc] = fmt::format("quickened: {}", vm::kFusedNames[vm::fused_of(code[pc])]);
  return notes;
}

// The build's date: SOURCE_DATE_EPOCH when set (reproducible builds,
// reproducible-builds.org/specs/source-date-epoch), else now.
uint64_t build_time_unix_s() {
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(epoch, &end, 10);
    if (*end == '\0') return v;
  }
  return static_cast<uint64_t>(std::time(nullptr));
}

int build(const BuildOptions& o) {
  const dialect::Dialect* d = choose_dialect(o.dialect, o.input, "build");
  if (d == nullptr) return 2;
  prepare_heap_for_compiling({o.input});
  dialect::CompileSettings settings;
  settings.created_unix_s = build_time_unix_s();
  const dialect::CompileOutput r = d->compile_file(o.input, settings);
  if (!r.diagnostics.empty()) fmt::print(stderr, "{}", format_text(r.diagnostics));
  if (!r.ok()) return 1;
  std::string error;
  bool written = false;
  if (o.emit == "asm") {
    if (!r.image) {
      fmt::print(stderr, "uprog build: the {} compiler makes no image to show as assembly\n",
                 d->name());
      return 1;
    }
    const std::string text = o.quickened
                                 ? bytecode::disassemble(*r.image, quickened_notes(*r.image))
                                 : bytecode::disassemble(*r.image);
    if (o.output == "-")
      return std::fwrite(text.data(), 1, text.size(), stdout) == text.size() ? 0 : 1;
    written = write_file_atomically(o.output.empty() ? o.input + ".s" : o.output, text.data(),
                                    text.size(), &error);
  } else {
    const std::string out = o.output.empty() ? d->stored_path(o.input) : o.output;
    written = write_file_atomically(out, r.stored_form.data(), r.stored_form.size(), &error);
    // The debug map beside it (PUP: X.cup.json), for `uprog sim --program X.cup` to debug by
    // source.
    if (written && !r.debug_map.empty())
      written =
          write_file_atomically(out + ".json", r.debug_map.data(), r.debug_map.size(), &error);
  }
  if (!written) {
    fmt::print(stderr, "uprog build: {}\n", error);
    return 1;
  }
  return 0;
}

void add_build(Options& cmd, Action& action) {
  auto o = std::make_shared<BuildOptions>();
  cmd.option("FILE", o->input, "source file").required();
  cmd.option("-o,--output", o->output,
             "output file (default FILE plus the stored form's extension, "
             "e.g. FILE.upi, or FILE.s with --emit asm; - writes the assembly to stdout)");
  cmd.option("--emit", o->emit, "image (the stored form) or asm").one_of({"image", "asm"});
  cmd.flag("--quickened", o->quickened,
           "with --emit asm: name the fused instruction the VM forms at load where one starts");
  add_dialect_option(cmd, o->dialect);
  cmd.on_chosen([&action, o] { action = [o] { return build(*o); }; });
}

const Subcommand kBuild("build", "Compile a source into the stored form a drive keeps", add_build);

}  // namespace
}  // namespace uprog::cli
