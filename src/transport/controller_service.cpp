// The simulated drive behind the transports (controller_service.h).
#include "transport/controller_service.h"

namespace uprog::transport {
namespace {

class ControllerChannel final : public LineChannel {
 public:
  ControllerChannel(ControllerService& service, std::unique_ptr<dialect::Session> session)
      : service_(service), session_(std::move(session)) {}
  std::vector<Reply> handle_line(std::string_view line) override {
    std::vector<Reply> replies = session_->send(line);
    service_.line_done();
    return replies;
  }

 private:
  ControllerService& service_;
  std::unique_ptr<dialect::Session> session_;
};

}  // namespace

std::vector<Reply> ControllerService::handle_line(std::string_view line) {
  std::vector<Reply> replies = controller_.send(line);
  line_done();
  return replies;
}

std::unique_ptr<LineChannel> ControllerService::open_channel() {
  return std::make_unique<ControllerChannel>(*this, controller_.open_session());
}

void ControllerService::advance(std::uint32_t us) {
  if (!keeper_ || !keeper_(std::uint64_t{us} * 1000)) controller_.advance(us);
  settle();
}

void ControllerService::line_done() {
  if (after_line_) after_line_();
  settle();
}

void ControllerService::settle() {
  for (const std::string& text : controller_.take_output()) publish_output(text);
  if (after_each_) after_each_();
}

}  // namespace uprog::transport
