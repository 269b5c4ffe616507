// The adapter that puts the simulated drive's firmware (controller::Controller) behind the
// transports' LineService interface.
#pragma once
#include "controller/controller.h"
#include "transport/line_service.h"

namespace uprog::transport {

class ControllerService final : public LineService {
 public:
  explicit ControllerService(controller::Controller& controller) : controller_(controller) {}

  std::vector<Reply> handle_line(std::string_view line) override;
  void advance(std::uint32_t us) override;

 private:
  controller::Controller& controller_;
};

}  // namespace uprog::transport
