// CRC-32 (IEEE 802.3, the zlib polynomial), used by the image header and the program store.
#pragma once
#include <cstddef>
#include <cstdint>

namespace uprog {

// Continues a CRC: pass the previous result as `crc` (0 to start).
uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

}  // namespace uprog
