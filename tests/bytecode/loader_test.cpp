// The container checks: each kind of damage to a binary image is refused with its own error.
#include <gtest/gtest.h>

#include <cstring>

#include "bytecode/image.h"
#include "bytecode/image_view.h"
#include "bytecode/opcodes.h"
#include "support/crc32.h"

namespace uprog::bytecode {
namespace {

Image small_image() {
  Image image;
  image.source_name = "t.ehl";
  image.code = {make_word(Op::RET, 0)};
  image.globals = {{"g", ValueType::Int, 3}};
  image.routines = {{"main", RoutineKind::Function, 0, 0, {}, 0}};
  image.lines = {{0, "t.ehl", 1}};
  return image;
}

void fix_crc(std::vector<uint8_t>& b) {
  const uint32_t crc = crc32(b.data() + kCrcStart, b.size() - kCrcStart);
  std::memcpy(b.data() + 12, &crc, 4);
}

LoadError load(const std::vector<uint8_t>& b) {
  ImageView view;
  return load_image(b.data(), b.size(), view);
}

// The offset of the section table entry of `kind`.
size_t section_entry(const std::vector<uint8_t>& b, Section kind) {
  uint32_t count;
  std::memcpy(&count, b.data() + 28, 4);
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t k;
    std::memcpy(&k, b.data() + kHeaderSize + i * kSectionEntrySize, 4);
    if (k == static_cast<uint32_t>(kind)) return kHeaderSize + i * kSectionEntrySize;
  }
  return 0;
}

TEST(Loader, AcceptsAGoodImage) { EXPECT_EQ(load(encode(small_image())), LoadError::Ok); }

TEST(Loader, RefusesShortImages) {
  auto b = encode(small_image());
  EXPECT_EQ(load({}), LoadError::TooShort);
  b.resize(kHeaderSize - 1);
  EXPECT_EQ(load(b), LoadError::TooShort);
}

TEST(Loader, RefusesForeignBytes) {
  auto b = encode(small_image());
  b[0] = 'X';
  EXPECT_EQ(load(b), LoadError::BadMagic);
}

TEST(Loader, RefusesOtherVersions) {
  auto b = encode(small_image());
  b[4] = static_cast<uint8_t>(kFormatVersion + 1);
  EXPECT_EQ(load(b), LoadError::BadVersion);
  b[4] = 1;  // version 1 had no dialect, texts or tasks
  EXPECT_EQ(load(b), LoadError::BadVersion);
}

TEST(Loader, RefusesTruncationAndPadding) {
  auto b = encode(small_image());
  auto longer = b;
  longer.push_back(0);
  EXPECT_EQ(load(longer), LoadError::BadSize);
  b.pop_back();
  EXPECT_EQ(load(b), LoadError::BadSize);
}

TEST(Loader, DetectsEveryFlippedBit) {
  const auto good = encode(small_image());
  for (size_t byte = kCrcStart; byte < good.size(); ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      auto b = good;
      b[byte] = static_cast<uint8_t>(b[byte] ^ (1u << bit));
      EXPECT_EQ(load(b), LoadError::BadCrc) << byte << ":" << bit;
    }
  }
}

TEST(Loader, RefusesABadSectionTable) {
  auto b = encode(small_image());
  const size_t constants = section_entry(b, Section::Constants);
  b[constants] = static_cast<uint8_t>(Section::Code);  // a second Code section
  fix_crc(b);
  EXPECT_EQ(load(b), LoadError::BadSectionTable);
}

TEST(Loader, RefusesSectionsOutsideTheImage) {
  auto b = encode(small_image());
  const size_t code = section_entry(b, Section::Code);
  const uint32_t far = 0x10000;
  std::memcpy(b.data() + code + 4, &far, 4);
  fix_crc(b);
  EXPECT_EQ(load(b), LoadError::BadSection);
}

TEST(Loader, RefusesUnterminatedStrings) {
  Image image = small_image();
  auto bytes = encode(image);
  const size_t strings = section_entry(bytes, Section::Strings);
  uint32_t offset, size;
  std::memcpy(&offset, bytes.data() + strings + 4, 4);
  std::memcpy(&size, bytes.data() + strings + 8, 4);
  bytes[offset + size - 1] = 'x';
  fix_crc(bytes);
  EXPECT_EQ(load(bytes), LoadError::BadString);
}

TEST(Loader, RefusesRecordsOutOfRange) {
  Image image = small_image();
  image.routines[0].entry = 5;  // past the code
  auto b = encode(image);
  EXPECT_EQ(load(b), LoadError::BadRecord);
  image = small_image();
  image.globals[0].length = 0;
  EXPECT_EQ(load(encode(image)), LoadError::BadRecord);
  image = small_image();
  image.events = {{1, 4}};  // no routine 4
  EXPECT_EQ(load(encode(image)), LoadError::BadRecord);
  image = small_image();
  image.lines = {{0, "a", 2}, {0, "a", 1}, {1, "a", 3}};
  EXPECT_EQ(load(encode(image)), LoadError::Ok);
  image.lines = {{1, "a", 2}, {0, "a", 1}};  // not sorted
  EXPECT_EQ(load(encode(image)), LoadError::BadRecord);
}

// The word at `index` of the first record of section `kind`.
size_t record_word(const std::vector<uint8_t>& b, Section kind, uint32_t index) {
  uint32_t offset;
  std::memcpy(&offset, b.data() + section_entry(b, kind) + 4, 4);
  return offset + index * 4;
}

void put_word(std::vector<uint8_t>& b, size_t at, uint32_t value) {
  std::memcpy(b.data() + at, &value, 4);
  fix_crc(b);
}

TEST(Loader, ReadsTheDialectTextsAndTasks) {
  Image image = small_image();
  image.dialect = "pdl";
  image.texts = {"x=%d", ""};
  image.tasks = {{0, 1, 62500, 3, true}};
  const auto b = encode(image);
  ImageView view;
  ASSERT_EQ(load_image(b.data(), b.size(), view), LoadError::Ok);
  EXPECT_STREQ(view.dialect_name(), "pdl");
  ASSERT_EQ(view.texts.size(), 2u);
  EXPECT_STREQ(view.text(0), "x=%d");
  EXPECT_STREQ(view.text(1), "");
  EXPECT_STREQ(view.text(2), "");  // past the table
  ASSERT_EQ(view.tasks.size(), 1u);
  const TaskRecord t = view.tasks[0];
  EXPECT_EQ(t.routine, 0u);
  EXPECT_EQ(t.number, 1u);
  EXPECT_EQ(t.period_ns, 62500u);
  EXPECT_EQ(t.priority, 3u);
  EXPECT_EQ(t.flags, kTaskStartsAtReset);
}

TEST(Loader, RefusesABadDialectOrText) {
  auto b = encode(small_image());
  put_word(b, 32, 0x7FFFFFFF);  // the dialect's string offset
  EXPECT_EQ(load(b), LoadError::BadString);
  Image image = small_image();
  image.texts = {"t"};
  b = encode(image);
  put_word(b, record_word(b, Section::Texts, 0), 0x7FFFFFFF);
  EXPECT_EQ(load(b), LoadError::BadString);
}

TEST(Loader, RefusesBadTaskRecords) {
  Image image = small_image();
  image.tasks = {{1, 0, 0, 0, false}};  // no routine 1
  EXPECT_EQ(load(encode(image)), LoadError::BadRecord);
  image.tasks = {{0, 0, 0, 0, false}};
  auto b = encode(image);
  ASSERT_EQ(load(b), LoadError::Ok);
  put_word(b, record_word(b, Section::Tasks, 4), 2);  // a flag no version defines
  EXPECT_EQ(load(b), LoadError::BadRecord);
}

TEST(Loader, SurvivesRandomBytes) {
  uint32_t seed = 12345;
  for (int round = 0; round < 2000; ++round) {
    std::vector<uint8_t> b(static_cast<size_t>(seed % 300));
    for (auto& x : b) {
      seed = seed * 1664525u + 1013904223u;
      x = static_cast<uint8_t>(seed >> 24);
    }
    if (b.size() >= 4) std::memcpy(b.data(), kMagic, 4);
    EXPECT_NE(load(b), LoadError::Ok);
  }
}

}  // namespace
}  // namespace uprog::bytecode
