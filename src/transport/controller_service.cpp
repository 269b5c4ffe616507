// Controller answers to transport replies (controller_service.h).
#include "transport/controller_service.h"

namespace uprog::transport {

std::vector<Reply> ControllerService::handle_line(std::string_view line) {
  std::vector<Reply> replies;
  for (auto& answer : controller_.send(line)) {
    std::string_view text = answer.text;
    // The wire form already marks an error with `?CODE`; "Error: " would say it twice.
    if (answer.is_error() && text.starts_with("Error: ")) text.remove_prefix(7);
    replies.push_back({std::string(text), answer.error});
  }
  return replies;
}

void ControllerService::advance(std::uint32_t us) {
  controller_.advance(us);
}

}  // namespace uprog::transport
