// The Gold number display rule (docs/dialects/gold-command-line.md) and expression splitting.
#include "dialects/gold/number_format.h"

#include <gtest/gtest.h>

#include "dialect/line_framer.h"
#include "dialects/gold/firmware.h"

namespace uprog::gold {
namespace {

TEST(controller_number_format, Integers) {
  EXPECT_EQ(format_gold_int(0), "0");
  EXPECT_EQ(format_gold_int(-2147483639), "-2147483639");
}

TEST(controller_number_format, Floats) {
  EXPECT_EQ(format_gold_float(3.6f), "3.600000");
  EXPECT_EQ(format_gold_float(2.0f / 3.0f), "0.666667");
  EXPECT_EQ(format_gold_float(10.0f), "10.0");
  EXPECT_EQ(format_gold_float(-4.5f), "-4.500000");
  EXPECT_EQ(format_gold_float(0.00255f), "0.002550");
  // 1.3.2: at most 7 significant digits; 1.7: abs(-123.54) "is 123.5400"
  EXPECT_EQ(format_gold_float(123.45678f), "123.4568");
  EXPECT_EQ(format_gold_float(1.2345678f), "1.234568");
  EXPECT_EQ(format_gold_float(2321.66458f), "2321.665");
  EXPECT_EQ(format_gold_float(123.54f), "123.5400");
  EXPECT_EQ(format_gold_float(9999999.0f), "9999999.0");
  EXPECT_EQ(format_gold_float(12345678.0f), "1.234568e07");
  EXPECT_EQ(format_gold_float(1.0e10f), "1.000000e10");
  EXPECT_EQ(format_gold_float(-2147483648.0f), "-2.147484e09");
  EXPECT_EQ(format_gold_float(99999999.0f), "1.000000e08");  // the mantissa's carry
}

std::vector<std::string> split_expressions(std::string_view text) {
  std::vector<std::string> out;
  for (const dialect::Frame& f : dialect::frame_text(text, command_line_framing()))
    out.push_back(f.text);
  return out;
}

TEST(controller_line_splitter, SemicolonsLineEndsAndComments) {
  EXPECT_EQ(split_expressions("PX=7; PX-3"), (std::vector<std::string>{"PX=7", "PX-3"}));
  EXPECT_EQ(split_expressions("3+4;\r\n5 ** six\n;;"), (std::vector<std::string>{"3+4", "5"}));
  EXPECT_TRUE(split_expressions("** only a comment").empty());
  EXPECT_TRUE(split_expressions("").empty());
}

}  // namespace
}  // namespace uprog::gold
