// Registration of the CLI's subcommands. Each subcommand lives in its own cmd_*.cpp file and
// registers itself with a static Subcommand object, so adding one touches no other file. A
// subcommand describes its options through Options; CLI11, header-only and slow to compile, is
// seen only by options.cpp.
#pragma once
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace uprog::cli {

// The action of the chosen subcommand returns the process's exit code.
using Action = std::function<int()>;

// One option of a subcommand, refined where it is added: cmd.option(...).required().
class Option {
 public:
  explicit Option(CLI::Option* option) : option_(option) {}
  Option& required();
  Option& show_default();  // the help shows the value the option starts with
  Option& one_of(std::initializer_list<const char*> values);
  Option& within(double low, double high);

 private:
  CLI::Option* option_;
};

// A subcommand's options, and what happens when the user chooses it.
class Options {
 public:
  explicit Options(CLI::App* app) : app_(app) {}
  Option option(const char* name, std::string& into, const char* help);
  Option option(const char* name, std::vector<std::string>& into, const char* help);
  Option option(const char* name, double& into, const char* help);
  Option option(const char* name, uint32_t& into, const char* help);
  void flag(const char* name, bool& into, const char* help);
  // Runs once the command line is parsed, when this subcommand was chosen.
  void on_chosen(std::function<void()> callback);

 private:
  CLI::App* app_;
};

// Adds the subcommand's options to `cmd`; its on_chosen stores what to run in `action`.
using AddOptions = void (*)(Options& cmd, Action& action);

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

// Parses the command line with every subcommand that may be meant, and runs the chosen one's
// action: the process's exit code (2 for a command line that does not parse).
int parse_and_run(int argc, char** argv);

}  // namespace uprog::cli
