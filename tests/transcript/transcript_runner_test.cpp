// The transcript runner reports mismatches, bad directives and unexpected errors.
#include <gtest/gtest.h>

#include "transcript/transcript.h"

namespace uprog::transcript {
namespace {

TranscriptResult run(const std::string& text) { return run_transcript_text(text, "t.txt", "."); }

TEST(controller_transcript, MatchingAnswersPass) {
  const TranscriptResult r = run("> 3+4\n< 7\n> AC=-5\n! 21\n> UI[1]=2\nwait 1ms\n> UI[1]\n< 2\n");
  EXPECT_TRUE(r.ok) << (r.failures.empty() ? "" : r.failures[0]);
  EXPECT_EQ(r.checks, 3);
}

TEST(controller_transcript, MismatchNamesFileAndLine) {
  const TranscriptResult r = run("# comment\n> 3+4\n< 8\n");
  ASSERT_FALSE(r.ok);
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0], "t.txt:3: expected '8', got '7'");
}

TEST(controller_transcript, ErrorWhereNoneExpectedFails) {
  EXPECT_FALSE(run("> AC=-5\n").ok);
  EXPECT_FALSE(run("> 3+4\n! 21\n").ok);
  EXPECT_FALSE(run("> AC=-5\n! 22\n").ok);
  EXPECT_TRUE(run("> AC=-5\n!\n").ok);
}

TEST(controller_transcript, MissingAndExtraAnswersFail) {
  EXPECT_FALSE(run("> 1;2\n< 1\n").ok);
  EXPECT_FALSE(run("> 1\n< 1\n< 2\n").ok);
}

TEST(controller_transcript, BadDirectivesFail) {
  EXPECT_FALSE(run("wait forever\n").ok);
  EXPECT_FALSE(run("input 9 = 1\n").ok);
  EXPECT_FALSE(run("fault nosuchfault\n").ok);
  EXPECT_FALSE(run("dialect pascal\n").ok);
  EXPECT_FALSE(run("frobnicate\n").ok);
  EXPECT_FALSE(run("< 7\n").ok);
  EXPECT_FALSE(run("load does/not/exist.ehl\n").ok);
}

// `drive axes=N phase_us=N` takes 1..4 axes and TS's range (25..2000 µs), and says so by place.
TEST(controller_transcript, TheDriveDirectiveChecksItsShape) {
  EXPECT_TRUE(run("drive axes=2 phase_us=100\n> TS\n< 100\n").ok);
  for (const char* bad : {"drive axes=5\n", "drive axes=0\n", "drive phase_us=24\n",
                          "drive phase_us=2001\n", "drive speed=3\n", "drive axes=1.5\n"}) {
    const TranscriptResult r = run(bad);
    ASSERT_FALSE(r.ok) << bad;
    ASSERT_EQ(r.failures.size(), 1u) << bad;
    EXPECT_EQ(r.failures[0].rfind("t.txt:1: drive takes axes=1..4 and phase_us=25..2000, not '", 0),
              0u)
        << r.failures[0];
  }
  const TranscriptResult late = run("> 1\n< 1\ndrive axes=2\n");
  ASSERT_FALSE(late.ok);
  EXPECT_EQ(late.failures.back(), "t.txt:3: drive must come before anything that uses the drive");
}

TEST(controller_transcript, Durations) {
  uint64_t us = 0;
  EXPECT_TRUE(parse_duration_us("500ms", us));
  EXPECT_EQ(us, 500000u);
  EXPECT_TRUE(parse_duration_us("2 s", us));
  EXPECT_EQ(us, 2000000u);
  EXPECT_TRUE(parse_duration_us("10us", us));
  EXPECT_EQ(us, 10u);
  EXPECT_FALSE(parse_duration_us("10", us));
  EXPECT_FALSE(parse_duration_us("-1s", us));
}

}  // namespace
}  // namespace uprog::transcript
