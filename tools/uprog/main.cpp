// uprog: compile, inspect and run servo-drive user programs. See docs/cli.md.
#include "commands.h"

int main(int argc, char** argv) { return uprog::cli::parse_and_run(argc, argv); }
