// The --input, --switch and --analog options (world_options.h).
#include "world_options.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdio>

#include "drive/axis.h"

namespace uprog::cli {
namespace {

// --input N=LEVEL: input N's electrical level, as a transcript's `input N = LEVEL`.
bool place_input(const std::string& s, controller::Controller& drive, std::string_view command) {
  int n = 0, level = 0;
  char tail = 0;
  if (std::sscanf(s.c_str(), "%d=%d%c", &n, &level, &tail) != 2 || n < 1 ||
      n > drive::kInputCount || (level != 0 && level != 1)) {
    fmt::print(stderr, "uprog {}: --input {}: expected N=LEVEL, N 1..{}, LEVEL 0 or 1, e.g. 2=1\n",
               command, s, drive::kInputCount);
    return false;
  }
  drive.axis().set_input_level(n, level == 1);
  return true;
}

// --switch N=FROM:TO: input N is high while the motor lies in [FROM, TO] counts, as the
// transcripts' `switch` directive places a home or limit cam.
bool place_switch(const std::string& s, controller::Controller& drive, std::string_view command) {
  int n = 0;
  double from = 0.0, to = 0.0;
  char tail = 0;
  if (std::sscanf(s.c_str(), "%d=%lf:%lf%c", &n, &from, &to, &tail) != 3 || n < 1 ||
      n > drive::kInputCount || !std::isfinite(from) || !std::isfinite(to) || !(from <= to)) {
    fmt::print(stderr,
               "uprog {}: --switch {}: expected N=FROM:TO, N 1..{}, FROM <= TO in motor "
               "counts, e.g. 5=40000:42000\n",
               command, s, drive::kInputCount);
    return false;
  }
  drive.axis().place_position_switch(n, from, to);
  return true;
}

// --analog N=MV (or MV): the dialect's drive takes it as its transcript directive `analog N =
// MV` (`analog = MV`); a drive without analog inputs refuses it.
bool place_analog(const std::string& s, controller::Controller& drive, std::string_view command) {
  const size_t eq = s.find('=');
  const std::string arg =
      eq == std::string::npos ? "= " + s : s.substr(0, eq) + " = " + s.substr(eq + 1);
  std::string failure;
  if (!drive.firmware().world_directive("analog", arg, failure)) {
    fmt::print(stderr, "uprog {}: --analog {}: the {} drive has no analog input\n", command, s,
               drive.dialect().name());
    return false;
  }
  if (!failure.empty()) {
    fmt::print(stderr, "uprog {}: --analog {}: {}\n", command, s, failure);
    return false;
  }
  return true;
}

}  // namespace

void add_world_options(Options& cmd, WorldOptions& world, bool with_inputs) {
  if (with_inputs)
    cmd.option("--input", world.inputs, "N=LEVEL: digital input N's level (0 or 1) from the start");
  cmd.option("--switch", world.switches,
             "N=FROM:TO: input N is high while the motor lies in [FROM, TO] counts (a cam)");
  cmd.option("--analog", world.analogs,
             "N=MV: analog input N's level in mV (ST: SW1, SW2; PUP: MV alone), as a "
             "transcript's `analog`");
}

bool place_world(const WorldOptions& world, controller::Controller& drive,
                 std::string_view command) {
  for (const std::string& s : world.inputs)
    if (!place_input(s, drive, command)) return false;
  for (const std::string& s : world.switches)
    if (!place_switch(s, drive, command)) return false;
  for (const std::string& s : world.analogs)
    if (!place_analog(s, drive, command)) return false;
  return true;
}

}  // namespace uprog::cli
