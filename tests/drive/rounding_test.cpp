// The servo cycle's rounding (drive/rounding.h) gives std::lround's answer for every double: the
// halves, the doubles next to them, the end of exact fractions (2^52), the fast path's limit
// (2^62), and what is no number.
#include "drive/rounding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace uprog::drive {
namespace {

TEST(Rounding, HalvesGoAwayFromZero) {
  EXPECT_EQ(round_half_away(0.5), 1);
  EXPECT_EQ(round_half_away(-0.5), -1);
  EXPECT_EQ(round_half_away(1.5), 2);
  EXPECT_EQ(round_half_away(2.5), 3);
  EXPECT_EQ(round_half_away(-2.5), -3);
  EXPECT_EQ(round_half_away(0.0), 0);
  EXPECT_EQ(round_half_away(-0.0), 0);
}

TEST(Rounding, MatchesTheLibraryAtTheEdges) {
  const double largest_below_half = std::nextafter(0.5, 0.0);  // 0.49999999999999994
  const double edges[] = {
      largest_below_half,
      -largest_below_half,
      std::nextafter(1.5, 0.0),
      std::nextafter(1.5, 2.0),
      4503599627370495.5,  // 2^52 - 0.5: the last half a double holds
      -4503599627370495.5,
      4503599627370496.0,
      9007199254740993.0,
      123456789.49999999,
      4611686018427387904.0 - 1024.0,  // just below 2^62: the fast path
      4611686018427387904.0,
      -4611686018427387904.0,
      1e300,
      -1e300,  // the library's
      std::numeric_limits<double>::denorm_min(),
      2147483647.5,
      -2147483648.5,
  };
  for (const double x : edges) EXPECT_EQ(round_half_away(x), std::lround(x)) << x;
}

TEST(Rounding, NoNumberIsTheLibrarysAnswer) {
  for (const double x :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()})
    EXPECT_EQ(round_half_away(x), std::lround(x)) << x;
}

TEST(Rounding, MatchesTheLibraryOnRandomCounts) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> counts(-3e9, 3e9);
  std::uniform_int_distribution<int64_t> halves(-6'000'000'000, 6'000'000'000);
  for (int i = 0; i < 100000; ++i) {
    const double x = counts(random);
    ASSERT_EQ(round_half_away(x), std::lround(x)) << x;
    const double half = static_cast<double>(halves(random)) + 0.5;
    ASSERT_EQ(round_half_away(half), std::lround(half)) << half;
  }
}

}  // namespace
}  // namespace uprog::drive
