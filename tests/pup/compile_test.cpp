// Every tests/pup/compile/X.pup compiles (date 01/01/00) to exactly X.cup, whose bytes were
// written by make_cup.py from the manual's and the spec's CUP lines.
#include <gtest/gtest.h>

#include <filesystem>

#include "dialects/pup/pup_compiler.h"
#include "support/files.h"

namespace uprog::pup {
namespace {

const std::filesystem::path kDir = std::filesystem::path(UPROG_SOURCE_DIR) / "tests/pup/compile";

std::string shown(const std::string& cup) {
  std::string s = cup;
  for (char& c : s) c = c == '\r' ? '\n' : c;
  return s;
}

TEST(PupCompile, EveryCaseGivesItsCupByteForByte) {
  int cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kDir)) {
    if (entry.path().extension() != ".pup") continue;
    ++cases;
    const PupOutput out = compile_pup_file(entry.path().string(), 0);
    ASSERT_TRUE(out.ok()) << entry.path() << ": " << format_text(out.diagnostics);
    std::filesystem::path expected_path = entry.path();
    expected_path.replace_extension(".cup");
    const auto expected = read_text_file(expected_path.string());
    ASSERT_TRUE(expected.has_value()) << expected_path;
    EXPECT_EQ(shown(write_cup(out.program)), shown(*expected)) << entry.path();
    EXPECT_EQ(write_cup(out.program), *expected) << entry.path() << " (line ends)";
    EXPECT_EQ(out.places.size(), out.program.lines.size());
  }
  EXPECT_GE(cases, 3);
}

TEST(PupCompile, EachCupLineKnowsItsPupLine) {
  const PupOutput out = compile_pup_file((kDir / "Demo1.pup").string(), 0);
  ASSERT_TRUE(out.ok());
  ASSERT_EQ(out.places.size(), 6u);
  EXPECT_EQ(out.places[0].line, 6);   // ASpeed = MY_SPEED
  EXPECT_EQ(out.places[3].line, 10);  // AWaitTime, 3000
  EXPECT_EQ(out.places[5].line, 12);
}

TEST(PupCompile, TheDateIsTheBuildTime) {
  EXPECT_EQ(cup_date(0), "01/01/00");
  EXPECT_EQ(cup_date(1389571200), "13/01/14");  // the manual's Demo1 header date
  EXPECT_EQ(cup_date(951782400), "29/02/00");
}

}  // namespace
}  // namespace uprog::pup
