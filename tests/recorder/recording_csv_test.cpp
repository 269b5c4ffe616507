// The CSV form: export, import and export again give the same bytes; a broken file is refused
// naming its line; comparisons name the first differing sample's channel and time.
#include "drive/recording_csv.h"

#include <gtest/gtest.h>

namespace uprog::drive {
namespace {

Recording sample_recording() {
  Recording r;
  r.sample_period_us = 250;
  r.trigger = "begin";
  r.pretrigger_percent = 20;
  r.trigger_index = 2;
  r.trigger_time_us = 1234500;
  r.channels = {{"PX", "counts", false, {0, 0, 3, -17, 2147483647}},
                {"cur", "A", true, {0.1f, -1.5f, 3.4e38f, 1e-7f, 0.0f}},
                {"cnt", "", false, {-2147483648.0, 1, 2, 3, 4}}};
  return r;
}

TEST(recording_csv, WritesASelfDescribingHeader) {
  const std::string csv = write_recording_csv(sample_recording());
  EXPECT_EQ(csv,
            "# uprog recording 1\n"
            "# sample_period_us: 250\n"
            "# trigger: begin\n"
            "# pretrigger_percent: 20\n"
            "# trigger_index: 2\n"
            "# trigger_time_us: 1234500\n"
            "# units: counts,A,\n"
            "# types: int,float,int\n"
            "time_us,PX,cur,cnt\n"
            "-500,0,0.1,-2147483648\n"
            "-250,0,-1.5,1\n"
            "0,3,3.4e+38,2\n"
            "250,-17,1e-07,3\n"
            "500,2147483647,0,4\n");
}

TEST(recording_csv, ExportImportExportIsByteIdentical) {
  const std::string first = write_recording_csv(sample_recording());
  std::string error;
  const std::optional<Recording> back = read_recording_csv(first, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(*back, sample_recording());
  EXPECT_EQ(write_recording_csv(*back), first);
}

TEST(recording_csv, RefusesBrokenFilesNamingTheLine) {
  const std::string good = write_recording_csv(sample_recording());
  auto error_of = [](std::string text) {
    std::string error;
    EXPECT_FALSE(read_recording_csv(text, &error));
    return error;
  };
  EXPECT_EQ(error_of(""), "line 1: the file is empty");
  EXPECT_EQ(error_of("time_us,PX\n0,1\n"), "line 1: expected '# uprog recording 1'");
  std::string t = good;
  t.replace(t.find("250\n"), 3, "x");
  EXPECT_EQ(error_of(t), "line 2: 'sample_period_us' needs a whole number, not 'x'");
  t = good;
  t.replace(t.find("-250,0,-1.5"), 11, "-250,0,abc");
  EXPECT_EQ(error_of(t), "line 11: 'abc' is no float (channel cur)");
  t = good;
  t.replace(t.find("0,3,3.4e+38"), 1, "7");
  EXPECT_EQ(error_of(t), "line 12: time '7', expected 0 (sample 2)");
  t = good;
  t.replace(t.find("250,-17,1e-07,3"), 15, "250,-17");
  EXPECT_EQ(error_of(t), "line 13: expected 4 cells, found 2");
  t = good;
  t.replace(t.find("500,2147483647"), 14, "500,2147483648");
  EXPECT_EQ(error_of(t), "line 14: '2147483648' is no int32 (channel PX)");
  t = good;
  t.replace(t.find("int,float"), 9, "int,text ");
  EXPECT_EQ(error_of(t), "line 8: type 'text ' is neither int nor float");
  EXPECT_EQ(error_of(good.substr(0, good.find("# units"))), "line 7: the file ends early");
}

TEST(recording_compare, NamesTheFirstDifferingSampleChannelAndTime) {
  const Recording expected = sample_recording();
  EXPECT_FALSE(compare(expected, expected, {}));
  Recording actual = expected;
  actual.channels[2].values[4] = 5;
  actual.channels[0].values[3] = -15;
  std::optional<Difference> d = compare(actual, expected, {});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "PX at 0.250 ms (sample 3): -15, expected -17 (tolerance 0)");
  d = compare(actual, expected, {{"PX", 2}});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "cnt at 0.500 ms (sample 4): 5, expected 4 (tolerance 0)");
  EXPECT_FALSE(compare(actual, expected, {{"PX", 2}, {"cnt", 1}}));
  d = compare(actual, expected, {{"VX", 2}});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "--tolerance VX: the reference has no channel 'VX'");
  actual = expected;
  actual.channels[0].values.pop_back();
  actual.channels[1].values.pop_back();
  actual.channels[2].values.pop_back();
  d = compare(actual, expected, {});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->text, "4 samples, expected 5 (they agree up to 0.500 ms)");
  actual = expected;
  actual.sample_period_us = 50;
  EXPECT_EQ(compare(actual, expected, {})->text, "sampling period 50 us, expected 250 us");
}

}  // namespace
}  // namespace uprog::drive
