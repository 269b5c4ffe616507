// The adapter that puts the simulated drive (controller::Controller) behind the transports'
// LineService interface: each host's lines pass through a session of its own, the drive's wire
// form is the firmware's, and what the drive sends on its own goes to every listener.
#pragma once
#include <functional>

#include "controller/controller.h"
#include "transport/line_service.h"

namespace uprog::transport {

class ControllerService final : public LineService {
 public:
  // `after_each` (optional) runs after every line and every advance: `uprog sim --log` prints
  // the firmware's log there.
  explicit ControllerService(controller::Controller& controller,
                             std::function<void()> after_each = {})
      : controller_(controller), after_each_(std::move(after_each)) {}

  std::vector<Reply> handle_line(std::string_view line) override;
  void advance(std::uint32_t us) override;
  // Each host gets a session of its own: its own download state.
  std::unique_ptr<LineChannel> open_channel() override;
  const dialect::WireForm& wire() const override { return controller_.firmware().wire(); }

  // A debugger attached to the drive lets time pass itself (it stops at a breakpoint and then
  // lets none pass): `keeper` gets each advance's nanoseconds and returns true when it took them;
  // false, or no keeper, and the drive advances as usual. `after_line` runs after each host line.
  void set_time_keeper(std::function<bool(std::uint64_t ns)> keeper,
                       std::function<void()> after_line) {
    keeper_ = std::move(keeper);
    after_line_ = std::move(after_line);
  }

  // Passes on what the drive sent on its own since the last call, then runs `after_each`.
  void settle();
  // After a host line: the keeper's look at it, then settle().
  void line_done();

 private:
  controller::Controller& controller_;
  std::function<void()> after_each_;
  std::function<bool(std::uint64_t ns)> keeper_;
  std::function<void()> after_line_;
};

}  // namespace uprog::transport
