// Registration of the CLI's subcommands. Each subcommand lives in its own cmd_*.cpp file and
// registers itself with a static Subcommand object, so adding one touches no other file.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace uprog::cli {

// The action of the chosen subcommand returns the process's exit code.
using Action = std::function<int()>;
// Adds the subcommand to `app`; its callback stores what to run in `action`.
using AddSubcommand = void (*)(CLI::App& app, Action& action);

std::vector<AddSubcommand>& subcommands();

struct Subcommand {
  explicit Subcommand(AddSubcommand add) { subcommands().push_back(add); }
};

}  // namespace uprog::cli
