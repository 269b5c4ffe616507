// uprog: compile, inspect and run servo-drive user programs. See docs/cli.md.
#include <cstring>

#include "commands.h"

namespace uprog::cli {

std::vector<const Subcommand*>& Subcommand::registry() {
  static std::vector<const Subcommand*> list;
  return list;
}

namespace {

// Only the subcommand the user named is built when argv[1] names one: building all of them
// (their options, validators and help) is a third of an empty `uprog run`'s start-up. With no
// or an unknown name, all are built, for the help and the error message.
std::vector<const Subcommand*> subcommands_for(int argc, char** argv) {
  const std::vector<const Subcommand*>& all = Subcommand::registry();
  if (argc > 1) {
    for (const Subcommand* s : all)
      if (std::strcmp(s->name, argv[1]) == 0) return {s};
  }
  return all;
}

}  // namespace

}  // namespace uprog::cli

int main(int argc, char** argv) {
  CLI::App app{"uprog: servo-drive user programs — compilers, VM and simulated drive"};
  app.set_version_flag("--version", "uprog " UPROG_VERSION);
  app.require_subcommand(1);
  uprog::cli::Action action;
  for (const uprog::cli::Subcommand* s : uprog::cli::subcommands_for(argc, argv))
    s->add_options(app.add_subcommand(s->name, s->description), action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return action ? action() : 2;
}
