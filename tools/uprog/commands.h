// Registration of the CLI's subcommands. Each subcommand lives in its own cmd_*.cpp file and
// registers itself with a static Subcommand object, so adding one touches no other file.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace uprog::cli {

// The action of the chosen subcommand returns the process's exit code.
using Action = std::function<int()>;
// Adds the subcommand's options to `cmd`; its callback stores what to run in `action`.
using AddOptions = void (*)(CLI::App* cmd, Action& action);

struct Subcommand {
  const char* name;  // what the user types: `uprog <name> ...`
  const char* description;
  AddOptions add_options;
  Subcommand(const char* name_, const char* description_, AddOptions add_options_)
      : name(name_), description(description_), add_options(add_options_) {
    registry().push_back(this);
  }
  static std::vector<const Subcommand*>& registry();
};

}  // namespace uprog::cli
