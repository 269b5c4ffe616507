// gnuplot from a recording (plot_recording.h): the samples go to a temporary CSV, a script
// stacks one panel per unit (channels without a unit share a panel "value") and gnuplot runs
// with it as its only argument, so no text of the user's reaches a shell.
#include "plot_recording.h"

#include <fmt/core.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <vector>

#include "drive/recording_csv.h"
#include "support/files.h"

extern char** environ;

namespace uprog::cli {
namespace {

// A gnuplot single-quoted string: a quote is doubled, nothing else is special.
std::string gp_string(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string temp_path(const char* suffix) {
  static int counter = 0;
  return (std::filesystem::temp_directory_path() /
          fmt::format("uprog-plot-{}-{}{}", getpid(), counter++, suffix))
      .string();
}

std::string script(const drive::Recording& r, const std::string& title, const std::string& data,
                   const std::string& out, bool svg) {
  std::map<std::string, std::vector<size_t>> panels;  // unit -> channel indices, in order of units
  std::vector<std::string> units;
  for (size_t c = 0; c < r.channels.size(); ++c) {
    const std::string unit = r.channels[c].unit.empty() ? "value" : r.channels[c].unit;
    if (!panels.count(unit)) units.push_back(unit);
    panels[unit].push_back(c);
  }
  const int height = 120 + 260 * static_cast<int>(units.size());
  std::string s;
  s += svg ? fmt::format("set terminal svg size 1000,{} dynamic background rgb 'white'\n", height)
           : fmt::format("set terminal pngcairo size 1000,{} font 'sans,10'\n", height);
  s += "set output " + gp_string(out) + "\n";
  s += "set datafile separator ','\nset datafile commentschars '#'\n";
  // Plain text (a '_' in a name is no subscript); the same margins and time range in every
  // panel, so that their time axes line up.
  s += "set termoption noenhanced\nset grid\nset key outside right top\nset lmargin 12\nset "
       "rmargin 18\n";
  s += fmt::format("set xrange [{}:{}]\n", static_cast<double>(r.time_us(0)) / 1000.0,
                   static_cast<double>(r.time_us(r.samples() - 1)) / 1000.0);
  s += fmt::format(
      "set multiplot layout {},1 title {}\n", units.size(),
      gp_string(fmt::format("{}: trigger {} at {:.3f} ms, {} samples every {} us", title, r.trigger,
                            static_cast<double>(r.trigger_time_us) / 1000.0, r.samples(),
                            r.sample_period_us)));
  // The trigger sample is at 0 ms: a dashed line through every panel.
  s += "set arrow 1 from first 0, graph 0 to first 0, graph 1 nohead dashtype 2 linecolor rgb "
       "'red' linewidth 1.5\n";
  s += "set label 1 'trigger' at first 0, graph 1 offset 0.5,-1 textcolor rgb 'red'\n";
  for (size_t p = 0; p < units.size(); ++p) {
    s += "set ylabel " + gp_string(units[p]) + "\n";
    s += p + 1 == units.size() ? "set xlabel 'time from the trigger, ms'\n" : "unset xlabel\n";
    s += "plot ";
    const std::vector<size_t>& cs = panels[units[p]];
    for (size_t k = 0; k < cs.size(); ++k) {
      s +=
          fmt::format("{}{} every ::1 using ($1/1000.0):{} with lines linewidth 1.5 title {}",
                      k ? ", " : "", gp_string(data), cs[k] + 2, gp_string(r.channels[cs[k]].name));
    }
    s += "\n";
  }
  s += "unset multiplot\n";
  return s;
}

bool run_gnuplot(const std::string& script_path, std::string* error) {
  const char* argv[] = {"gnuplot", script_path.c_str(), nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, "gnuplot", nullptr, nullptr, const_cast<char* const*>(argv), environ) !=
      0) {
    *error = "cannot run gnuplot (scripts/install-deps installs it: Debian's gnuplot-nox)";
    return false;
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    *error = "gnuplot failed on " + script_path;
    return false;
  }
  return true;
}

}  // namespace

bool plot_recording(const drive::Recording& recording, const std::string& title,
                    const std::string& out_path, std::string* error) {
  const std::string ext = std::filesystem::path(out_path).extension().string();
  if (ext != ".png" && ext != ".svg") {
    *error = out_path + ": the plot's file ends in .png or .svg";
    return false;
  }
  if (recording.samples() == 0) {
    *error = "the recording has no samples to plot";
    return false;
  }
  const std::string data = temp_path(".csv"), gp = temp_path(".gp");
  const std::string csv = drive::write_recording_csv(recording);
  const std::string text = script(recording, title, data, out_path, ext == ".svg");
  bool ok = write_file_atomically(data, csv.data(), csv.size(), error) &&
            write_file_atomically(gp, text.data(), text.size(), error) && run_gnuplot(gp, error);
  std::error_code ec;
  std::filesystem::remove(data, ec);
  if (ok) std::filesystem::remove(gp, ec);  // a failed script stays for a look
  return ok;
}

}  // namespace uprog::cli
