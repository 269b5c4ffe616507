// The supported range of image format versions (format.h): every version in it loads, one
// outside it is refused, and the refusal a drive gives at download and at boot (both load the
// bytes through dialect::LoadedProgram) names the image's version and the range it reads.
#include <gtest/gtest.h>

#include <string>

#include "bytecode/image.h"
#include "bytecode/image_view.h"
#include "bytecode/opcodes.h"
#include "dialect/loaded_program.h"

namespace uprog::bytecode {
namespace {

class NoCommands final : public vm::Host {
 public:
  virtual ~NoCommands() = default;
  vm::CommandStatus read(uint32_t, int32_t, Value&) override { return {}; }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return {}; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override { return {}; }
  uint32_t now_us() override { return 0; }
};

std::vector<uint8_t> image_of_version(uint16_t version) {
  Image image;
  image.source_name = "t.ehl";
  image.code = {make_word(Op::RET, 0)};
  image.routines = {{"main", RoutineKind::Function, 0, 0, {}, 0}};
  image.lines = {{0, "t.ehl", 1}};
  std::vector<uint8_t> bytes = encode(image);
  bytes[4] = static_cast<uint8_t>(version & 0xFF);  // the CRC starts after the header's version
  bytes[5] = static_cast<uint8_t>(version >> 8);
  return bytes;
}

std::string refusal(const std::vector<uint8_t>& bytes) {
  NoCommands host;
  std::string why;
  const auto loaded = dialect::LoadedProgram::load(bytes, vm::MachineConfig{}, host, &why);
  return loaded ? "loaded" : why;
}

TEST(FormatVersion, TheRangeIsOrderedAndTheWriterMakesItsNewest) {
  static_assert(kMinFormatVersion <= kMaxFormatVersion);
  static_assert(kFormatVersion == kMaxFormatVersion);
  EXPECT_EQ(image_format_version(image_of_version(kFormatVersion).data(), kHeaderSize),
            kFormatVersion);
}

TEST(FormatVersion, EveryVersionInTheRangeLoads) {
  for (uint16_t v = kMinFormatVersion; v <= kMaxFormatVersion; ++v) {
    const auto bytes = image_of_version(v);
    ImageView view;
    EXPECT_EQ(load_image(bytes.data(), bytes.size(), view), LoadError::Ok) << v;
    EXPECT_EQ(refusal(bytes), "loaded") << v;
  }
}

TEST(FormatVersion, AnOlderImageIsRefusedNamingBothVersions) {
  const uint16_t older = kMinFormatVersion - 1;
  const std::string expected = "not a valid image: unsupported image format version " +
                               std::to_string(older) + "; this firmware reads versions " +
                               std::to_string(kMinFormatVersion) + " to " +
                               std::to_string(kMaxFormatVersion);
  EXPECT_EQ(refusal(image_of_version(older)), expected);
}

TEST(FormatVersion, ANewerImageIsRefusedNamingBothVersions) {
  const uint16_t newer = kMaxFormatVersion + 1;
  const std::string expected = "not a valid image: unsupported image format version " +
                               std::to_string(newer) + "; this firmware reads versions " +
                               std::to_string(kMinFormatVersion) + " to " +
                               std::to_string(kMaxFormatVersion);
  EXPECT_EQ(refusal(image_of_version(newer)), expected);
  EXPECT_NE(refusal(image_of_version(0xFFFF)).find("version 65535;"), std::string::npos);
}

TEST(FormatVersion, NoImageHasNoVersion) {
  const uint8_t foreign[8] = {'X', 'P', 'R', 'G', 4, 0, 36, 0};
  EXPECT_EQ(image_format_version(foreign, sizeof foreign), 0);
  EXPECT_EQ(image_format_version(foreign, 3), 0);
  EXPECT_EQ(image_format_version(nullptr, 0), 0);
}

}  // namespace
}  // namespace uprog::bytecode
