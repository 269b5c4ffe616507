// What the command-line fuzz targets share: the input cut into host lines as a terminal sends
// them, each given to the drive, then 20 ms of virtual time so that whatever the lines started
// runs for a bounded while; what the drive said is dropped.
#pragma once
#include <string_view>

#include "controller/controller.h"

namespace uprog::fuzz {

template <class SendLine>
void send_lines_then_run(controller::Controller& drive, std::string_view input, SendLine send) {
  while (!input.empty()) {
    const size_t end = input.find('\n');
    (void)send(input.substr(0, end));
    if (end == std::string_view::npos) break;
    input.remove_prefix(end + 1);
  }
  drive.advance(20'000);
  (void)drive.take_log();
  (void)drive.take_output();
}

}  // namespace uprog::fuzz
