// uprog: compile, inspect and run servo-drive user programs. See docs/cli.md.
#include <fmt/core.h>

#include "commands.h"

namespace uprog::cli {

std::vector<AddSubcommand>& subcommands() {
  static std::vector<AddSubcommand> list;
  return list;
}

}  // namespace uprog::cli

int main(int argc, char** argv) {
  CLI::App app{"uprog: servo-drive user programs — compilers, VM and simulated drive"};
  app.require_subcommand(1);
  uprog::cli::Action action;
  for (auto add : uprog::cli::subcommands()) add(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return action ? action() : 2;
}
