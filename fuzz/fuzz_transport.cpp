// libFuzzer target: the wire protocol's framing (src/dialect, src/transport). The host's bytes go through a
// LineFramer in one piece and in chunks the input chooses, which must give the same frames, and
// through a HostSession whose service echoes each line; the drive's answers go back through the
// host's AnswerReader. Memory must stay bounded by the line limit.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/line_framer.h"
#include "dialect/semicolon_wire.h"
#include "transport/answer_reader.h"
#include "transport/host_session.h"

namespace {

// Answers every line with its own text, and an error for lines starting with '!'; its wire is
// the semicolon wire with the framing the input chose.
class EchoService final : public uprog::transport::LineService {
 public:
  explicit EchoService(uprog::dialect::FramerOptions options) : wire_(options) {}
  std::vector<uprog::transport::Reply> handle_line(std::string_view line) override {
    if (!line.empty() && line[0] == '!') return {{std::string(line.substr(1)), 19}};
    return {{std::string(line), 0}};
  }
  void advance(std::uint32_t) override {}
  const uprog::dialect::WireForm& wire() const override { return wire_; }

 private:
  uprog::dialect::SemicolonWire wire_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog::transport;
  using uprog::dialect::FramerOptions, uprog::dialect::LineFramer, uprog::dialect::Frame;
  if (size < 2) return 0;
  // Byte 0: options; byte 1: the chunk size for the chunked feed.
  FramerOptions options;
  options.max_line_length = 1 + (data[0] & 0x3f) * 8;
  options.semicolon_ends_line = (data[0] & 0x40) == 0;
  if (data[0] & 0x80) options.comment_marker = "";
  const size_t chunk = 1 + data[1] % 17;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 2), size - 2);

  LineFramer whole(options), pieces(options);
  std::vector<Frame> a, b;
  whole.feed(bytes, a);
  for (size_t at = 0; at < bytes.size(); at += chunk) {
    pieces.feed(bytes.substr(at, chunk), b);
    if (pieces.pending_size() > options.max_line_length) abort();
  }
  if (a != b) abort();  // the chunking must not change what the drive sees
  for (const Frame& f : a)
    if (f.kind == Frame::Kind::kLine && f.text.size() > options.max_line_length) abort();

  EchoService service(options);
  HostSession session(service);
  std::string wire;
  for (size_t at = 0; at < bytes.size(); at += chunk) session.receive(bytes.substr(at, chunk), wire);
  session.disconnect();

  AnswerReader reader;
  std::vector<AnswerEvent> events;
  reader.feed(wire, events);
  reader.feed(bytes, events);  // and whatever a confused drive might send
  return 0;
}
