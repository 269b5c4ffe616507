// Registration of the CLI's subcommands: each subcommand file adds itself to the app.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace uprog::cli {

// The action of the chosen subcommand returns the process's exit code.
using Action = std::function<int()>;

void add_asm(CLI::App& app, Action& action);
void add_disasm(CLI::App& app, Action& action);
void add_exec(CLI::App& app, Action& action);

}  // namespace uprog::cli
