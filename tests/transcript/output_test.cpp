// The transcript directives for what the drive sends on its own (`output`, `quiet`) and the
// `dialect` line, on a dialect the registry does not know (the contract tests' toy).
#include <gtest/gtest.h>

#include "controller/toy_dialect.h"
#include "transcript/transcript.h"

namespace uprog::transcript {
namespace {

TranscriptResult run_toy(const std::string& text) {
  return run_transcript_text(text, "t.txt", ".", {}, &toy::dialect());
}

TEST(transcript_output, OutputLinesAreTakenOldestFirstAndQuietWantsNone) {
  const TranscriptResult r =
      run_toy("quiet\n> say one\n> say two\noutput one\noutput two   \nquiet\n");
  EXPECT_TRUE(r.ok) << (r.failures.empty() ? "" : r.failures[0]);
  EXPECT_EQ(r.checks, 4);
}

TEST(transcript_output, AMissingOrDifferentLineFailsWithItsPlace) {
  TranscriptResult r = run_toy("> say one\noutput two\n");
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0], "t.txt:2: expected output 'two', got 'one'");
  r = run_toy("output one\n");
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0], "t.txt:1: expected output 'one', got none");
  r = run_toy("> say one\nquiet\n");
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0], "t.txt:2: expected no output, got 'one'");
}

TEST(transcript_output, ADialectLineChoosesTheDriveAndMustComeFirst) {
  EXPECT_TRUE(run_transcript_text("dialect gold\n> 3+4\n< 7\n", "t.txt", ".").ok);
  TranscriptResult r = run_transcript_text("dialect nosuch\n", "t.txt", ".");
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0], "t.txt:1: no dialect named 'nosuch' (uprog dialects lists them)");
  r = run_transcript_text("> 3+4\ndialect toy\n", "t.txt", ".");
  EXPECT_FALSE(r.ok);  // the drive already runs Gold; and the registry has no toy
}

}  // namespace
}  // namespace uprog::transcript
