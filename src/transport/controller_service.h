// The adapter that puts the simulated drive's firmware (controller::Controller) behind the
// transports' LineService interface; each host's lines pass through its own controller::Connection.
#pragma once
#include "controller/connection.h"
#include "controller/controller.h"
#include "transport/line_service.h"

namespace uprog::transport {

// The controller's answers as the wire's replies ("Error: " dropped: `?CODE` already says it).
std::vector<Reply> to_replies(std::vector<controller::Answer> answers);

class ControllerService final : public LineService {
 public:
  explicit ControllerService(controller::Controller& controller) : controller_(controller) {}

  std::vector<Reply> handle_line(std::string_view line) override;
  void advance(std::uint32_t us) override;
  // Each host gets a controller::Connection: its own download state.
  std::unique_ptr<LineChannel> open_channel() override;

 private:
  controller::Controller& controller_;
};

}  // namespace uprog::transport
