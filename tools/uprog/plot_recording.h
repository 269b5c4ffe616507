// Draws a recording with gnuplot (installed by scripts/install-deps): one panel per unit, time
// in ms from the trigger on the x axis, the trigger marked. `uprog plot` and `uprog run --plot`.
#pragma once
#include <string>

#include "drive/recording.h"

namespace uprog::cli {

// Writes FILE.png or FILE.svg (by its extension); false with `error` set when it cannot.
bool plot_recording(const drive::Recording& recording, const std::string& title,
                    const std::string& out_path, std::string* error);

}  // namespace uprog::cli
