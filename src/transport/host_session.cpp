// A host's conversation: frames to the line service, answers to their wire form (host_session.h).
#include "transport/host_session.h"

namespace uprog::transport {

using dialect::Frame;

HostSession::HostSession(LineService& service)
    : service_(service), channel_(service.open_channel()), framer_(service.wire().framing()) {}

void HostSession::disconnect() {
  framer_.reset();
  channel_ = service_.open_channel();
}

void HostSession::deliver_output(std::string_view text, std::string& out) const {
  service_.wire().write_output(text, out);
}

void HostSession::deliver_lost_output(uint64_t count, std::string& out) const {
  service_.wire().write_lost_output(count, out);
}

void HostSession::receive(std::string_view bytes, std::string& out) {
  // A drive that echoes sends each byte back before it answers the line the byte ends.
  if (!service_.wire().echoes()) return take(bytes, out);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    service_.wire().write_echo(bytes.substr(i, 1), out);
    take(bytes.substr(i, 1), out);
  }
}

void HostSession::take(std::string_view bytes, std::string& out) {
  const dialect::WireForm& wire = service_.wire();
  frames_.clear();
  framer_.feed(bytes, frames_);
  for (const Frame& frame : frames_) {
    switch (frame.kind) {
      case Frame::Kind::kLine: {
        const auto replies =
            channel_ ? channel_->handle_line(frame.text) : service_.handle_line(frame.text);
        if (replies.empty()) wire.write_silent_line(out);
        for (const Reply& reply : replies) wire.write_answer(reply, out);
        break;
      }
      case Frame::Kind::kTooLong:
        wire.write_answer(wire.framing_error({"Line too long", kErrorLineTooLong}), out);
        break;
      case Frame::Kind::kBadCharacter:
        wire.write_answer(wire.framing_error({"Bad character", kErrorBadCharacter}), out);
        break;
      case Frame::Kind::kLineBreak:
        wire.write_line_end(out);
        break;
    }
  }
}

}  // namespace uprog::transport
