// uprog: compile, inspect and run servo-drive user programs. See docs/cli.md.
#include <fmt/core.h>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"uprog: servo-drive user programs — compilers, VM and simulated drive"};
  app.require_subcommand(1);
  uprog::cli::Action action;
  uprog::cli::add_asm(app, action);
  uprog::cli::add_disasm(app, action);
  uprog::cli::add_exec(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return action ? action() : 2;
}
