// SV/LD storage: round trip, atomic file, corruption refused.
#include "drive/parameter_store.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "drive/axis.h"

namespace uprog::drive {
namespace {

Parameters sample_parameters() {
  Parameters p;
  p.user_ints[0] = -7;
  p.user_ints[23] = 2147483647;
  p.user_floats[4] = 0.1f;
  p.user_floats[23] = -1.5e30f;
  p.gains.kp[2] = 1.234567e-5f;
  p.input_logic[2] = 21;
  p.speed_counts_per_s = 12345;
  p.smoothing_ms = 9;
  p.unit_mode = 2;
  return p;
}

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("uprog_drive_") + name)).string();
}

TEST(drive_parameter_store, RoundTripIsExact) {
  const Parameters p = sample_parameters();
  const auto back = parse_parameters(serialize_parameters(p));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, p);
  EXPECT_NE(*back, Parameters{});
}

TEST(drive_parameter_store, SaveAndLoadFile) {
  const std::string path = temp_path("save_load.txt");
  ASSERT_TRUE(save_parameters(sample_parameters(), path));
  const auto back = load_parameters(path);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, sample_parameters());
  std::filesystem::remove(path);
}

TEST(drive_parameter_store, CorruptFileIsRefused) {
  std::string text = serialize_parameters(sample_parameters());
  const size_t at = text.find("SP=12345");
  ASSERT_NE(at, std::string::npos);
  text[at + 3] = '9';
  std::string error;
  EXPECT_FALSE(parse_parameters(text, &error).has_value());
  EXPECT_NE(error.find("CRC"), std::string::npos);
  EXPECT_FALSE(parse_parameters(text.substr(0, text.size() / 2)).has_value());
  EXPECT_FALSE(parse_parameters("").has_value());
  EXPECT_FALSE(load_parameters(temp_path("does_not_exist.txt")).has_value());
}

TEST(drive_parameter_store, LoadIntoAxisNeedsMotorOff) {
  Axis axis;
  axis.set_motor_on(true);
  EXPECT_EQ(axis.load_parameters(sample_parameters()), Status::kMotorOn);
  axis.set_motor_on(false);
  EXPECT_EQ(axis.load_parameters(sample_parameters()), Status::kOk);
  EXPECT_EQ(axis.parameters().speed_counts_per_s, 12345);
}

}  // namespace
}  // namespace uprog::drive
