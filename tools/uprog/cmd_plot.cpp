// `uprog plot RECORDING.csv -o FILE.png|.svg`: a recording (uprog run --csv, a transcript's
// record) drawn with gnuplot, one panel per unit, time in ms from the trigger.
#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>

#include "commands.h"
#include "drive/recording_csv.h"
#include "plot_recording.h"
#include "support/files.h"

namespace uprog::cli {
namespace {

struct PlotOptions {
  std::string csv;
  std::string out;
  std::string title;
};

int plot(const PlotOptions& o) {
  std::string error;
  const std::optional<std::string> text = read_text_file(o.csv, &error);
  if (!text) {
    fmt::print(stderr, "uprog plot: {}\n", error);
    return 2;
  }
  const std::optional<drive::Recording> r = drive::read_recording_csv(*text, &error);
  if (!r) {
    fmt::print(stderr, "uprog plot: {}: {}\n", o.csv, error);
    return 2;
  }
  const std::string title =
      o.title.empty() ? std::filesystem::path(o.csv).filename().string() : o.title;
  if (!plot_recording(*r, title, o.out, &error)) {
    fmt::print(stderr, "uprog plot: {}\n", error);
    return 2;
  }
  fmt::print("{}\n", o.out);
  return 0;
}

void add_plot(Options& cmd, Action& action) {
  auto o = std::make_shared<PlotOptions>();
  cmd.option("RECORDING", o->csv, "a recording's CSV file (uprog run --record ... --csv)")
      .required();
  cmd.option("-o,--output", o->out, "the picture: FILE.png or FILE.svg").required();
  cmd.option("--title", o->title, "the plot's title (default: the recording's file name)");
  cmd.on_chosen([&action, o] { action = [o] { return plot(*o); }; });
}

const Subcommand kPlot("plot", "Draw a recording (CSV) as a PNG or SVG with gnuplot", add_plot);

}  // namespace
}  // namespace uprog::cli
