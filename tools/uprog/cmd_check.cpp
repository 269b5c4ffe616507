// `uprog check FILE...`: compiles sources, each in its dialect, and prints their diagnostics (gcc
// style or JSON); exit 0 when all are clean, 1 when any has errors.
#include <fmt/core.h>

#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "dialect_choice.h"
#include "huge_heap.h"

namespace uprog::cli {
namespace {

struct CheckOptions {
  std::vector<std::string> files;
  std::string format = "text";
  std::string dialect;
  std::vector<std::string> defines;  // -D NAME=value
};

int check(const CheckOptions& o) {
  std::vector<Diagnostic> all;
  bool errors = false;
  dialect::CompileSettings settings;
  settings.check_only = true;  // every diagnostic of a build, without building the stored form
  for (const std::string& d : o.defines) {
    const size_t eq = d.find('=');
    if (eq == 0 || eq == std::string::npos || eq + 1 == d.size()) {
      fmt::print(stderr, "uprog check: -D {}: expected NAME=value\n", d);
      return 2;
    }
    settings.defines.emplace_back(d.substr(0, eq), d.substr(eq + 1));
  }
  prepare_heap_for_compiling(o.files);
  for (const std::string& f : o.files) {
    const dialect::Dialect* d = choose_dialect(o.dialect, f, "check");
    if (d == nullptr) return 2;
    dialect::CompileOutput r = d->compile_file(f, settings);
    errors = errors || !r.ok();
    all.insert(all.end(), r.diagnostics.begin(), r.diagnostics.end());
  }
  if (o.format == "json")
    fmt::print("{}\n", format_json(all));
  else
    fmt::print("{}", format_text(all));
  return errors ? 1 : 0;
}

void add_check(Options& cmd, Action& action) {
  auto o = std::make_shared<CheckOptions>();
  cmd.option("FILE", o->files, "source files").required();
  cmd.option("--format", o->format, "text or json").one_of({"text", "json"});
  add_dialect_option(cmd, o->dialect);
  cmd.option(
      "-D", o->defines,
      "NAME=value: a name the preprocessor sees with that value (ST: a drive parameter in #IF)");
  cmd.on_chosen([&action, o] { action = [o] { return check(*o); }; });
}

const Subcommand kCheck("check", "Compile sources and report diagnostics", add_check);

}  // namespace
}  // namespace uprog::cli
