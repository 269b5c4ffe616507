// `uprog check FILE...`: compiles Gold sources and prints their diagnostics (gcc style or
// JSON); exit 0 when all are clean, 1 when any has errors.
#include <fmt/core.h>

#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "dialects/gold/compile.h"
#include "huge_heap.h"

namespace uprog::cli {
namespace {

void add_check(CLI::App* cmd, Action& action) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("FILE", *files, "Gold source files")->required();
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  cmd->callback([&action, files, format] {
    action = [files, format] {
      std::vector<Diagnostic> all;
      bool errors = false;
      prepare_heap_for_compiling(*files);
      for (const std::string& f : *files) {
        gold::CompileOptions options;
        options.check_only = true;  // every diagnostic of a build, without building the image
        const gold::CompileResult r = gold::compile_file(f, options);
        errors = errors || !r.ok();
        all.insert(all.end(), r.diagnostics.begin(), r.diagnostics.end());
      }
      if (*format == "json") fmt::print("{}\n", format_json(all));
      else fmt::print("{}", format_text(all));
      return errors ? 1 : 0;
    };
  });
}

const Subcommand kCheck("check", "Compile Gold sources and report diagnostics", add_check);

}  // namespace
}  // namespace uprog::cli
