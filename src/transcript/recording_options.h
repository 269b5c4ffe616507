// What `uprog run --record …` and a transcript's `record` line ask of the drive's recorder, made
// into recorder settings: channels by name, a trigger in words, pre-trigger share, length, gap.
#pragma once
#include <cstdint>
#include <string>

#include "controller/controller.h"
#include "drive/recorder.h"
#include "drive/recording.h"

namespace uprog::transcript {

struct RecordRequest {
  std::string channels;               // "PX,VX,cnt"
  std::string trigger = "immediate";  // immediate, begin, rising:CH:LEVEL, falling:CH:LEVEL,
                                      // leave:CH:LOW:HIGH, enter:CH:LOW:HIGH, input:N:rise|fall
  uint32_t pretrigger_percent = 0;
  uint32_t gap_cycles = 1;
  uint32_t length = 1000;
  bool early_trigger = false;
};

// "" when `out` holds the settings, else why not ("no channel 'PQ': …", "trigger 'x': …").
std::string recorder_settings(controller::Controller& drive, const RecordRequest& request,
                              drive::RecorderSettings& out);
// A transcript's `record CHANNELS [trigger=SPEC] [pretrigger=P] [length=N] [gap=N]`: arms the
// recorder; "" or why not.
std::string record_directive(controller::Controller& drive, const std::string& arg);
// A transcript's `expect FILE.csv [CH=TOLERANCE ...]`: the recorder's recording against the file
// (relative to `base_dir`); "" when they agree, else "FILE: the first difference".
std::string expect_directive(controller::Controller& drive, const std::string& arg,
                             const std::string& base_dir);

// "CH=VALUE"; false when it is not.
bool parse_tolerance(const std::string& text, drive::Tolerance& out);
// A whole number 0..max from text; false when it is not.
bool parse_count(const std::string& text, uint32_t max, uint32_t& out);

}  // namespace uprog::transcript
