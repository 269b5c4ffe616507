// A recording as a CSV file with a self-describing header (docs/recorder.md, "The CSV file"):
// written and read back so that export, import and export again give the same bytes.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "drive/recording.h"

namespace uprog::drive {

std::string write_recording_csv(const Recording& recording);
// nullopt with `error` = "line N: what is wrong" for a file that is not such a recording.
std::optional<Recording> read_recording_csv(std::string_view text, std::string* error);

}  // namespace uprog::drive
