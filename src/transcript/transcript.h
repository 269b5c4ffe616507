// Replays a transcript (shared/spec/transcript.md, docs/transcripts.md) on a fresh simulated
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

// `name` is used in messages; `base_dir` resolves `load` paths.
// `dialect` is the drive's until the transcript names one (nullptr: the registry's default).
TranscriptResult run_transcript_text(const std::string& text, const std::string& name,
                                     const std::string& base_dir, const controller::Timing& timing = {},
                                     const dialect::Dialect* dialect = nullptr);
TranscriptResult run_transcript_file(const std::string& path, const controller::Timing& timing = {},
                                     const dialect::Dialect* dialect = nullptr);

// "500ms", "2s", "10us", "1.5s" -> microseconds; false when it is not a duration.
bool parse_duration_us(const std::string& text, uint64_t& out_us);
// `40ph`: 40 of the firmware's cycles (a PDL drive's phases).
bool parse_cycles(const std::string& text, uint64_t& out);

}  // namespace uprog::transcript
