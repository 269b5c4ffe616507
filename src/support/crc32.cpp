// CRC-32 a nibble at a time, with a 16-entry table computed at compile time: the freestanding
// core's code size matters more than the speed of a check made once a load (scripts/footprint).
#include "support/crc32.h"

#include <array>

namespace uprog {
namespace {

constexpr std::array<uint32_t, 16> make_table() {
  std::array<uint32_t, 16> table{};
  for (uint32_t n = 0; n < 16; ++n) {
    uint32_t c = n;
    for (int k = 0; k < 4; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}
constexpr std::array<uint32_t, 16> kTable = make_table();

}  // namespace

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc) {
  crc = ~crc;
  for (size_t i = 0; i < size; ++i) {
    crc = kTable[(crc ^ data[i]) & 0xFu] ^ (crc >> 4);
    crc = kTable[(crc ^ (data[i] >> 4)) & 0xFu] ^ (crc >> 4);
  }
  return ~crc;
}

}  // namespace uprog
