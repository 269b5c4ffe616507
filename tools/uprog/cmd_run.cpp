// `uprog run FILE`: runs a program on a fresh simulated drive of its dialect in virtual time and
// prints what happened (the firmware's log, the drive's output, the final state); --then lines go
// to the command line after.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "controller/controller.h"
#include "dialect_choice.h"
#include "drive/axis.h"
#include "drive/recording_csv.h"
#include "drive_shape.h"
#include "plot_recording.h"
#include "support/files.h"
#include "transcript/recording_options.h"
#include "transcript/transcript.h"
#include "world_options.h"

namespace uprog::cli {
namespace {

struct RunOptions {
  std::string file;
  std::string dialect;
  DriveShape shape;
  std::string entry;
  std::string duration;  // empty: until the program has ended and the axis is still
  std::string limit = "60s";
  std::string budget = "1";
  std::vector<std::string> inputs;  // N=LEVEL@TIME
  std::vector<std::string> faults;  // NAME@TIME
  WorldOptions world;               // --switch, --analog
  std::string record;               // PX,VX,myvar
  std::string trigger = "immediate";
  std::string pretrigger = "0";
  std::string length;  // empty: the whole run (immediate, no pre-trigger) or 1000
  std::string gap = "1";
  std::string csv;
  std::string plot;
  std::string expect;
  std::vector<std::string> tolerances;  // CH=VALUE
  std::vector<std::string> then;
};

struct Scheduled {
  uint64_t at_us;
  int input = 0;
  bool level = false;
  std::string fault;  // empty for an input
};

bool parse_schedule(const RunOptions& o, std::vector<Scheduled>& out) {
  for (const std::string& s : o.inputs) {
    const size_t eq = s.find('='), at = s.find('@');
    Scheduled e;
    if (eq == std::string::npos || at == std::string::npos || at < eq ||
        !transcript::parse_duration_us(s.substr(at + 1), e.at_us)) {
      fmt::print(stderr, "uprog run: --input {}: expected N=LEVEL@TIME, e.g. 2=1@500ms\n", s);
      return false;
    }
    const std::string n = s.substr(0, eq), level = s.substr(eq + 1, at - eq - 1);
    if (n.size() != 1 || n[0] < '1' || n[0] > '6' || (level != "0" && level != "1")) {
      fmt::print(stderr, "uprog run: --input {}: N is 1..6 and LEVEL 0 or 1\n", s);
      return false;
    }
    e.input = n[0] - '0';
    e.level = level == "1";
    out.push_back(e);
  }
  for (const std::string& s : o.faults) {
    const size_t at = s.find('@');
    Scheduled e;
    if (at == std::string::npos || !transcript::parse_duration_us(s.substr(at + 1), e.at_us)) {
      fmt::print(stderr, "uprog run: --fault {}: expected NAME@TIME, e.g. feedback@1s\n", s);
      return false;
    }
    e.fault = s.substr(0, at);
    out.push_back(e);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Scheduled& a, const Scheduled& b) { return a.at_us < b.at_us; });
  return true;
}

std::string shown(const controller::Answer& a) {
  return a.is_error() ? fmt::format("Error: {} (EC {})", a.text, a.error) : a.text;
}

// Arms the drive's recorder for --record before any time passes; "" or why not.
std::string arm_recorder(controller::Controller& drive, const RunOptions& o, uint64_t duration_us,
                         bool& length_given) {
  transcript::RecordRequest request;
  request.channels = o.record;
  request.trigger = o.trigger;
  request.early_trigger = true;  // a BG right after the start still gets its recording
  if (!transcript::parse_count(o.pretrigger, 100, request.pretrigger_percent))
    return "--pretrigger takes 0..100";
  if (!transcript::parse_count(o.gap, 1u << 20, request.gap_cycles) || request.gap_cycles == 0)
    return "--gap takes a number of servo cycles, 1 or more";
  length_given = !o.length.empty();
  if (length_given) {
    if (!transcript::parse_count(o.length, UINT32_MAX, request.length) || request.length == 0)
      return "--length takes a number of samples, 1 or more";
  } else if (o.trigger == "immediate" && request.pretrigger_percent == 0) {
    // The whole run, as far as the recorder's memory goes.
    const uint64_t cycles =
        duration_us / std::max<uint64_t>(drive.axis().period_us(), 1) / request.gap_cycles + 1;
    const size_t channels =
        static_cast<size_t>(std::count(o.record.begin(), o.record.end(), ',') + 1);
    request.length =
        static_cast<uint32_t>(std::min<uint64_t>(cycles, drive::kMaxRecorderWords / channels));
  }
  drive::RecorderSettings settings;
  if (std::string why = transcript::recorder_settings(drive, request, settings); !why.empty())
    return "--record: " + why;
  std::string why;
  if (!drive.recorder().arm(settings, &why)) return "--record: " + why;
  return {};
}

// After the run: the recording to --csv, --plot and --expect; 0, or the exit code.
int finish_recording(controller::Controller& drive, const RunOptions& o,
                     const std::vector<drive::Tolerance>& tolerances) {
  const std::optional<drive::Recording> r = drive.recorder().recording(drive.axis().period_us());
  if (!r) {
    fmt::print(stderr, "uprog run: the recorder was never triggered ({}), nothing recorded\n",
               o.trigger);
    return 4;
  }
  std::string error;
  if (!o.csv.empty()) {
    const std::string csv = drive::write_recording_csv(*r);
    if (!write_file_atomically(o.csv, csv.data(), csv.size(), &error)) {
      fmt::print(stderr, "uprog run: {}\n", error);
      return 2;
    }
  }
  if (!o.plot.empty()) {
    if (!plot_recording(*r, o.file, o.plot, &error)) {
      fmt::print(stderr, "uprog run: {}\n", error);
      return 2;
    }
    fmt::print("plot: {}\n", o.plot);
  }
  if (o.expect.empty()) return 0;
  const std::optional<std::string> text = read_text_file(o.expect, &error);
  const std::optional<drive::Recording> expected =
      text ? drive::read_recording_csv(*text, &error) : std::nullopt;
  if (!expected) {
    fmt::print(stderr, "uprog run: --expect {}: {}\n", o.expect, error);
    return 2;
  }
  if (const std::optional<drive::Difference> d = drive::compare(*r, *expected, tolerances)) {
    fmt::print(stderr, "uprog run: the recording differs from {}: {}\n", o.expect, d->text);
    return 5;
  }
  fmt::print("recording matches {} ({} samples)\n", o.expect, r->samples());
  return 0;
}

int run(const RunOptions& o) {
  controller::ControllerOptions copts;
  copts.dialect = choose_dialect(o.dialect, o.file, "run");
  if (copts.dialect == nullptr) return 2;
  apply(o.shape, copts);
  if (o.budget == "unlimited") {
    copts.timing.unlimited = true;
  } else {
    const long n = std::strtol(o.budget.c_str(), nullptr, 10);
    if (n <= 0 || std::to_string(n) != o.budget) {
      fmt::print(stderr,
                 "uprog run: --budget takes a positive number of lines per pass or 'unlimited'\n");
      return 2;
    }
    copts.timing.lines_per_cycle = static_cast<uint32_t>(n);
  }
  uint64_t duration_us = 0;
  const bool until_idle = o.duration.empty();
  const std::string& span = until_idle ? o.limit : o.duration;
  if (!transcript::parse_duration_us(span, duration_us)) {
    fmt::print(stderr, "uprog run: {}: expected a duration such as 500ms or 2s\n", span);
    return 2;
  }
  std::vector<Scheduled> schedule;
  if (!parse_schedule(o, schedule)) return 2;
  const bool recording = !o.record.empty();
  if (recording && o.csv.empty() && o.plot.empty() && o.expect.empty()) {
    fmt::print(stderr,
               "uprog run: --record needs --csv OUT, --plot FILE.png or --expect REFERENCE.csv\n");
    return 2;
  }
  std::vector<drive::Tolerance> tolerances;
  for (const std::string& t : o.tolerances) {
    drive::Tolerance tol;
    if (!transcript::parse_tolerance(t, tol)) {
      fmt::print(stderr, "uprog run: --tolerance {}: expected CHANNEL=VALUE, e.g. PX=2\n", t);
      return 2;
    }
    tolerances.push_back(tol);
  }

  controller::Controller drive(copts);
  if (!place_world(o.world, drive, "run")) return 2;
  std::vector<Diagnostic> diagnostics;
  const bool compiled = drive.download_source_file(o.file, diagnostics);
  if (!diagnostics.empty()) fmt::print(stderr, "{}", format_text(diagnostics));
  if (!compiled) return 1;
  if (const std::string why = drive.start_program(o.entry); !why.empty()) {
    fmt::print(stderr, "uprog run: {}\n", why);
    return 1;
  }

  const uint64_t period = drive.axis().period_us();
  bool length_given = false;
  if (recording) {
    const std::string why = arm_recorder(drive, o, duration_us, length_given);
    if (!why.empty()) {
      fmt::print(stderr, "uprog run: {}\n", why);
      return 2;
    }
  }
  bool run_time_error = false;
  auto print_log = [&] {
    for (const controller::LogEntry& e : drive.take_log()) {
      fmt::print("[{:10.3f} ms] {}\n", static_cast<double>(e.time_us) / 1000.0, e.text);
      // Every dialect's firmware logs a run-time error as such ("task 1: run-time error 4 ...").
      if (e.text.find("run-time error") != std::string::npos) run_time_error = true;
    }
    for (const std::string& text : drive.take_output()) fmt::print("{}", text);
  };
  size_t next = 0;
  const uint64_t start = drive.now_us();
  // Without --for, the run ends once the program has ended, nothing is scheduled any more and
  // the axis is at rest (in position, or its motor off): what the motor did is then complete.
  const auto idle = [&] {
    // A recording of a given length goes on after the trigger until it is complete.
    const bool recording_on =
        length_given && drive.recorder().state() == drive::RecorderState::kTriggered;
    return until_idle && !drive.program_running() && next == schedule.size() &&
           drive.axis().at_rest() && !recording_on;
  };
  while (drive.now_us() - start < duration_us && !idle()) {
    while (next < schedule.size() && schedule[next].at_us <= drive.now_us() - start) {
      const Scheduled& e = schedule[next++];
      if (e.fault.empty()) {
        drive.set_input_level(e.input, e.level);
        fmt::print("[{:10.3f} ms] input {} = {}\n", static_cast<double>(drive.now_us()) / 1000.0,
                   e.input, e.level ? 1 : 0);
      } else if (drive.inject_fault(e.fault)) {
        fmt::print("[{:10.3f} ms] fault {}\n", static_cast<double>(drive.now_us()) / 1000.0,
                   e.fault);
      } else {
        fmt::print(stderr, "uprog run: no fault named '{}'\n", e.fault);
        return 2;
      }
    }
    drive.advance(std::min<uint64_t>(period * 20, duration_us - (drive.now_us() - start)));
    print_log();
  }
  int recording_result = 0;
  if (recording) recording_result = finish_recording(drive, o, tolerances);
  fmt::print("after {:.3f} ms: {}", static_cast<double>(drive.now_us() - start) / 1000.0,
             drive.firmware().state_summary());
  if (drive.program_error() != 0)
    fmt::print(" error={} ({})", drive.program_error(), drive.program_error_text());
  fmt::print("\n");
  for (const std::string& line : o.then) {
    for (const controller::Answer& a : drive.send(line)) fmt::print("{}\n", shown(a));
  }
  print_log();
  if (recording_result != 0) return recording_result;
  return run_time_error ? 3 : 0;
}

void add_run(Options& cmd, Action& action) {
  auto o = std::make_shared<RunOptions>();
  cmd.option("FILE", o->file, "source file").required();
  add_dialect_option(cmd, o->dialect);
  cmd.option("--entry", o->entry,
             "where to start (a routine of the program; default: where its dialect starts one)");
  cmd.option("--for", o->duration,
             "virtual time to run (default: until the program has ended and the axis is still)");
  cmd.option("--limit", o->limit, "without --for, the longest virtual time to run").show_default();
  add_drive_shape_options(cmd, o->shape);
  cmd.option("--budget", o->budget, "source lines per background pass, or 'unlimited' (default 1)");
  cmd.option("--input", o->inputs, "N=LEVEL@TIME: set digital input N at TIME");
  add_world_options(cmd, o->world, /*with_inputs=*/false);
  cmd.option("--fault", o->faults, "NAME@TIME: latch a drive fault at TIME");
  cmd.option(
      "--record", o->record,
      "comma-separated channels for the drive's recorder: signals and globals (PX,VX,myvar)");
  cmd.option("--trigger", o->trigger,
             "immediate, begin, rising:CH:LEVEL, falling:CH:LEVEL, leave:CH:LOW:HIGH, "
             "enter:CH:LOW:HIGH, input:N:rise|fall")
      .show_default();
  cmd.option("--pretrigger", o->pretrigger, "percent of the recording before the trigger")
      .show_default();
  cmd.option("--length", o->length,
             "samples per channel (default: the whole run with an immediate trigger, else 1000)");
  cmd.option("--gap", o->gap, "servo cycles between samples").show_default();
  cmd.option("--csv", o->csv, "where the recording goes (docs/recorder.md, \"The CSV file\")");
  cmd.option("--plot", o->plot, "draw the recording: FILE.png or FILE.svg");
  cmd.option("--expect", o->expect,
             "a reference recording (CSV): the run fails where this one differs");
  cmd.option("--tolerance", o->tolerances, "CHANNEL=VALUE: how far --expect lets a channel differ");
  cmd.option("--then", o->then, "a command line sent after the run; its answers are printed");
  cmd.on_chosen([&action, o] { action = [o] { return run(*o); }; });
}

const Subcommand kRun("run", "Run a program on a fresh simulated drive in virtual time", add_run);

}  // namespace
}  // namespace uprog::cli
