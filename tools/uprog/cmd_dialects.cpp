// `uprog dialects`: the dialects this build knows, with their file extensions.
#include <fmt/core.h>

#include "commands.h"
#include "dialects/registry.h"

namespace uprog::cli {
namespace {

int list_dialects() {
  for (const dialect::Dialect* d : dialects::all()) {
    std::string extensions;
    for (std::string_view e : d->source_extensions())
      extensions += (extensions.empty() ? "" : " ") + std::string(e);
    fmt::print("{:<6} {:<12} -> {:<5} {}\n", d->name(), extensions, d->stored_extension(),
               d->description());
  }
  return 0;
}

void add_dialects(Options& cmd, Action& action) {
  cmd.on_chosen([&action] { action = [] { return list_dialects(); }; });
}

const Subcommand kDialects("dialects", "List the dialects: name, source extensions, stored form",
                           add_dialects);

}  // namespace
}  // namespace uprog::cli
