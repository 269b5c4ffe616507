// Controller answers to transport replies (controller_service.h).
#include "transport/controller_service.h"

namespace uprog::transport {

namespace {

class ControllerChannel final : public LineChannel {
 public:
  explicit ControllerChannel(controller::Controller& controller) : connection_(controller) {}
  std::vector<Reply> handle_line(std::string_view line) override {
    return to_replies(connection_.send(line));
  }

 private:
  controller::Connection connection_;
};

}  // namespace

std::vector<Reply> to_replies(std::vector<controller::Answer> answers) {
  std::vector<Reply> replies;
  for (auto& answer : answers) {
    std::string_view text = answer.text;
    // The wire form already marks an error with `?CODE`; "Error: " would say it twice.
    if (answer.is_error() && text.starts_with("Error: ")) text.remove_prefix(7);
    replies.push_back({std::string(text), answer.error});
  }
  return replies;
}

std::vector<Reply> ControllerService::handle_line(std::string_view line) {
  return to_replies(controller_.send(line));
}

std::unique_ptr<LineChannel> ControllerService::open_channel() {
  return std::make_unique<ControllerChannel>(controller_);
}

void ControllerService::advance(std::uint32_t us) {
  controller_.advance(us);
}

}  // namespace uprog::transport
