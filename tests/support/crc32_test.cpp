// The CRC-32 of the image header and the program store is the standard one (IEEE 802.3, zlib's):
// its published check value, and a CRC continued over parts equals the CRC of the whole.
#include "support/crc32.h"

#include <gtest/gtest.h>

#include <string_view>

namespace uprog::test {
namespace {

const uint8_t* bytes(std::string_view s) { return reinterpret_cast<const uint8_t*>(s.data()); }

TEST(Crc32, TheStandardCheckValue) {
  constexpr std::string_view kCheck = "123456789";
  EXPECT_EQ(crc32(bytes(kCheck), kCheck.size()), 0xCBF43926u);
  EXPECT_EQ(crc32(nullptr, 0), 0u);
  // zlib's crc32 of "The quick brown fox jumps over the lazy dog"
  constexpr std::string_view kFox = "The quick brown fox jumps over the lazy dog";
  EXPECT_EQ(crc32(bytes(kFox), kFox.size()), 0x414FA339u);
}

TEST(Crc32, ContinuesOverParts) {
  constexpr std::string_view kText = "a program's stored form, in two parts";
  const uint32_t whole = crc32(bytes(kText), kText.size());
  const uint32_t first = crc32(bytes(kText), 10);
  EXPECT_EQ(crc32(bytes(kText) + 10, kText.size() - 10, first), whole);
}

}  // namespace
}  // namespace uprog::test
