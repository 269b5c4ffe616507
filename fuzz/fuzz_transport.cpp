// libFuzzer target: the wire protocol's framing (src/dialect, src/transport). The host's bytes go
// through a LineFramer in one piece and in chunks the input chooses, which must give the same
// frames, and through a HostSession whose service echoes each line; the drive's answers go back
// through the host's EchoFilter and AnswerReader. Memory must stay bounded by the line limit.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/line_framer.h"
#include "dialect/semicolon_wire.h"
#include "echo_service.h"
#include "transport/answer_reader.h"
#include "transport/echo_filter.h"
#include "transport/host_session.h"

namespace {

// The semicolon wire, echoing every byte as a real Elmo drive does while EO=1 when `echo` is set.
class EchoingWire final : public uprog::dialect::WireForm {
 public:
  EchoingWire(uprog::dialect::FramerOptions options, bool echo) : plain_(options), echo_(echo) {}
  uprog::dialect::FramerOptions framing() const override { return plain_.framing(); }
  void write_answer(const uprog::dialect::Answer& a, std::string& out) const override {
    plain_.write_answer(a, out);
  }
  void write_silent_line(std::string& out) const override { plain_.write_silent_line(out); }
  void write_line_end(std::string& out) const override { plain_.write_line_end(out); }
  void write_output(std::string_view text, std::string& out) const override {
    plain_.write_output(text, out);
  }
  void write_echo(std::string_view bytes, std::string& out) const override { out += bytes; }
  bool echoes() const override { return echo_; }

 private:
  uprog::dialect::SemicolonWire plain_;
  bool echo_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog::transport;
  using uprog::dialect::FramerOptions, uprog::dialect::LineFramer, uprog::dialect::Frame;
  if (size < 2) return 0;
  // Byte 0: options; byte 1: empty expressions answered (bit 7), an echoing drive (bit 6), the
  // chunk size for the chunked feed (the rest).
  FramerOptions options;
  options.max_line_length = 1 + (data[0] & 0x3f) * 8;
  options.semicolon_ends_line = (data[0] & 0x40) == 0;
  if (data[0] & 0x80) options.comment_marker = "";
  options.answer_empty_expressions = (data[1] & 0x80) != 0;
  const bool echo = (data[1] & 0x40) != 0;
  const size_t chunk = 1 + (data[1] & 0x3f) % 17;
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

  EchoService<EchoingWire> service(options, echo);
  HostSession session(service);
  std::string wire;
  for (size_t at = 0; at < bytes.size(); at += chunk)
    session.receive(bytes.substr(at, chunk), wire);
  session.disconnect();

  // The host takes what would be the echo out, in the same chunks; it never adds a byte.
  EchoFilter filter;
  filter.expect(bytes, ";\r\n");
  std::string answers;
  for (size_t at = 0; at < wire.size(); at += chunk)
    filter.feed(std::string_view(wire).substr(at, chunk), answers);
  if (answers.size() > wire.size()) abort();

  AnswerReader reader;
  std::vector<AnswerEvent> events;
  reader.feed(answers, events);
  reader.feed(bytes, events);  // and whatever a confused drive might send
  return 0;
}
