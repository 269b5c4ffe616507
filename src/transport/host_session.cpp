// A host's conversation: frames to the line service, answers to their wire form (host_session.h).
#include "transport/host_session.h"

namespace uprog::transport {

HostSession::HostSession(LineService& service, FramerOptions options)
    : service_(service), channel_(service.open_channel()), framer_(options) {}

void HostSession::disconnect() {
  framer_.reset();
  channel_ = service_.open_channel();
}

void HostSession::receive(std::string_view bytes, std::string& out) {
  frames_.clear();
  framer_.feed(bytes, frames_);
  for (const Frame& frame : frames_) {
    switch (frame.kind) {
      case Frame::Kind::kLine: {
        const auto replies = channel_ ? channel_->handle_line(frame.text) : service_.handle_line(frame.text);
        if (replies.empty()) out.push_back(';');
        for (const Reply& reply : replies) append_wire_reply(reply, out);
        break;
      }
      case Frame::Kind::kTooLong:
        append_wire_reply({"Line too long", kErrorLineTooLong}, out);
        break;
      case Frame::Kind::kBadCharacter:
        append_wire_reply({"Bad character", kErrorBadCharacter}, out);
        break;
      case Frame::Kind::kLineBreak:
        out += "\r\n";
        break;
    }
  }
}

}  // namespace uprog::transport
