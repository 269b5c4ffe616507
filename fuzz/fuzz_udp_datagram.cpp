// libFuzzer target: the UDP port's datagram boundary (transport/udp_server.h). The input is cut
// into datagrams (each a length byte, then up to that many bytes; a length of 255 stands for an
// oversized datagram of the rest repeated past the line limit); each goes through one peer's
// DatagramHost, whose service answers every line with its own text. A reply never exceeds the
// largest UDP payload, an empty datagram gets none, and the peer's memory stays bounded.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/semicolon_wire.h"
#include "echo_service.h"
#include "transport/udp_server.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog::transport;
  if (size < 1) return 0;
  // Byte 0: the framing (line limit, `;` ends a line, empty expressions answered).
  uprog::dialect::FramerOptions options;
  options.max_line_length = 1 + (data[0] & 0x3f) * 8;
  options.semicolon_ends_line = (data[0] & 0x40) == 0;
  options.answer_empty_expressions = (data[0] & 0x80) != 0;
  EchoService<uprog::dialect::SemicolonWire> service(options);
  DatagramHost peer(service);
  size_t at = 1;
  while (at < size) {
    const size_t length = data[at++];
    std::string datagram;
    if (length == 255) {
      const std::string_view rest(reinterpret_cast<const char*>(data + at), size - at);
      while (!rest.empty() && datagram.size() <= options.max_line_length + 1) datagram += rest;
      at = size;
    } else {
      const size_t n = length < size - at ? length : size - at;
      datagram.assign(reinterpret_cast<const char*>(data + at), n);
      at += n;
    }
    const std::string reply = peer.answer(datagram);
    if (reply.size() > kMaxDatagramBytes) abort();
    if (datagram.empty() && !reply.empty()) abort();
    if (peer.output(datagram).size() > kMaxDatagramBytes) abort();
  }
  return 0;
}
