// libFuzzer target: arbitrary bytes as an image through Machine::load (container check and
// verifier), then, if it loads, every routine run for a bounded budget with a fake Host.
// The input is tried as it is, and with its size and CRC fields made right, so that mutations
// get past the CRC to the section parser and the verifier.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "bytecode/format.h"
#include "run_image.h"
#include "support/crc32.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  fuzz::load_and_run(data, size);
  if (size < bytecode::kHeaderSize || size > UINT32_MAX) return 0;
  std::vector<uint8_t> fixed(data, data + size);
  const uint32_t total = static_cast<uint32_t>(size);
  std::memcpy(fixed.data() + 8, &total, 4);
  const uint32_t crc = crc32(fixed.data() + bytecode::kCrcStart, size - bytecode::kCrcStart);
  std::memcpy(fixed.data() + 12, &crc, 4);
  fuzz::load_and_run(fixed.data(), fixed.size());
  return 0;
}
