// The world's inputs a host tester sets on the simulated drive from the start, as a transcript's
// `input`, `switch` and `analog` directives set them (docs/transcripts.md): `uprog sim` takes
// all three, `uprog run` the cam switches and analog levels (its --input is timed).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "commands.h"
#include "controller/controller.h"

namespace uprog::cli {

struct WorldOptions {
  std::vector<std::string> inputs;    // N=LEVEL
  std::vector<std::string> switches;  // N=FROM:TO
  std::vector<std::string> analogs;   // N=MV, or MV for a drive with one analog input
};

// Adds `--switch` and `--analog` to `cmd`, and `--input N=LEVEL` when `with_inputs`.
void add_world_options(Options& cmd, WorldOptions& world, bool with_inputs);
// Places them on the drive's first axis and its firmware; false with the reason printed,
// "uprog COMMAND: --switch …".
bool place_world(const WorldOptions& world, controller::Controller& drive,
                 std::string_view command);

}  // namespace uprog::cli
