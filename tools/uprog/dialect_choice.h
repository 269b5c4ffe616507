// How every subcommand picks the dialect of a file: `--dialect NAME`, else the file's extension
// (dialects/registry.h), else Gold's default. One place, so all subcommands agree.
#pragma once
#include <string>

#include "commands.h"
#include "dialect/dialect.h"

namespace uprog::cli {

// Adds `--dialect NAME` to `cmd`, stored in `name`.
void add_dialect_option(Options& cmd, std::string& name);
// The dialect for `path`: nullptr (with the reason printed as "uprog COMMAND: ...") when
// `name` names no dialect.
const dialect::Dialect* choose_dialect(const std::string& name, const std::string& path,
                                       const char* command);

}  // namespace uprog::cli
