// The --dialect option and the choice of a file's dialect (dialect_choice.h).
#include "dialect_choice.h"

#include <fmt/core.h>

#include "dialects/registry.h"

namespace uprog::cli {

void add_dialect_option(Options& cmd, std::string& name) {
  cmd.option("--dialect", name,
             "the program's dialect (default: from the file's extension; `uprog dialects`)");
}

const dialect::Dialect* choose_dialect(const std::string& name, const std::string& path,
                                       const char* command) {
  if (!name.empty()) {
    const dialect::Dialect* d = dialects::find(name);
    if (d == nullptr)
      fmt::print(stderr, "uprog {}: no dialect named '{}' (uprog dialects lists them)\n", command,
                 name);
    return d;
  }
  if (const dialect::Dialect* d = dialects::for_file(path)) return d;
  return &dialects::default_dialect();
}

}  // namespace uprog::cli
