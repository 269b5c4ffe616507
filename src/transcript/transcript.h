// Replays a transcript (docs/transcripts.md) on a fresh simulated
// drive of its dialect: lines sent to the command line, answers and output expected, time and the
// world changed between them.
#pragma once
#include <string>
#include <vector>

#include "controller/controller.h"

namespace uprog::transcript {

struct TranscriptResult {
  bool ok = false;
  int checks = 0;                     // answers compared
  std::vector<std::string> failures;  // "FILE:LINE: expected …, got …"
};

// Directives that a layer above the transcript adds (the debugger's `debug ...`), and how time
// passes while it holds the drive. Without one, a transcript knows only its own directives.
class Extension {
 public:
  virtual ~Extension() = default;
  // `name arg` that the runner does not know: false when the extension does not know it either;
  // a check that fails says why in `failure`.
  virtual bool directive(controller::Controller& drive, const std::string& name,
                         const std::string& arg, std::string& failure) = 0;
  // `wait`: the extension lets the time pass as it decides (a stopped program's drive: none).
  virtual void wait(controller::Controller& drive, uint64_t us) = 0;
  // True while `>` lines must take no virtual time (they go to the drive as queries).
  virtual bool holds_time() const = 0;
};

// `name` is used in messages; `base_dir` resolves `load` paths.
// `dialect` is the drive's until the transcript names one (nullptr: the registry's default).
TranscriptResult run_transcript_text(const std::string& text, const std::string& name,
                                     const std::string& base_dir,
                                     const controller::Timing& timing = {},
                                     const dialect::Dialect* dialect = nullptr,
                                     Extension* extension = nullptr);
TranscriptResult run_transcript_file(const std::string& path, const controller::Timing& timing = {},
                                     const dialect::Dialect* dialect = nullptr,
                                     Extension* extension = nullptr);

// "500ms", "2s", "10us", "1.5s" -> microseconds; false when it is not a duration.
bool parse_duration_us(const std::string& text, uint64_t& out_us);
// `40ph`: 40 of the firmware's cycles (a PDL drive's phases).
bool parse_cycles(const std::string& text, uint64_t& out);

}  // namespace uprog::transcript
