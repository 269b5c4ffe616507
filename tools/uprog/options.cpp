// The one file of the CLI that includes CLI11: the subcommands' options (commands.h's Options)
// and the parse of the command line. Kept apart because CLI11 is header-only and each file that
// includes it took 8–14 s of compiler time.
#include <CLI/CLI.hpp>
#include <cstring>

#include "commands.h"

namespace uprog::cli {

Option& Option::required() {
  option_->required();
  return *this;
}
Option& Option::show_default() {
  option_->capture_default_str();
  return *this;
}
Option& Option::one_of(std::initializer_list<const char*> values) {
  option_->check(CLI::IsMember(std::vector<std::string>(values.begin(), values.end())));
  return *this;
}
Option& Option::within(double low, double high) {
  option_->check(CLI::Range(low, high));
  return *this;
}

Option Options::option(const char* name, std::string& into, const char* help) {
  return Option(app_->add_option(name, into, help));
}
Option Options::option(const char* name, std::vector<std::string>& into, const char* help) {
  return Option(app_->add_option(name, into, help));
}
Option Options::option(const char* name, double& into, const char* help) {
  return Option(app_->add_option(name, into, help));
}
Option Options::option(const char* name, uint32_t& into, const char* help) {
  return Option(app_->add_option(name, into, help));
}
void Options::flag(const char* name, bool& into, const char* help) {
  app_->add_flag(name, into, help);
}
void Options::on_chosen(std::function<void()> callback) { app_->callback(std::move(callback)); }

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

int parse_and_run(int argc, char** argv) {
  CLI::App app{"uprog: servo-drive user programs — compilers, VM and simulated drive"};
  app.set_version_flag("--version", "uprog " UPROG_VERSION);
  app.require_subcommand(1);
  Action action;
  for (const Subcommand* s : subcommands_for(argc, argv)) {
    Options options(app.add_subcommand(s->name, s->description));
    s->add_options(options, action);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return action ? action() : 2;
}

}  // namespace uprog::cli
