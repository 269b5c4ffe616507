// The transcript directives `record` and `expect`: a differing recording fails naming the
// channel and the time, bad settings are refused with their reason, all on the line they are on.
#include <gtest/gtest.h>

#include "transcript/transcript.h"

namespace uprog::transcript {
namespace {

const std::string kDir = std::string(UPROG_SOURCE_DIR) + "/tests/transcripts/recorder";

TEST(transcript_recorder, ASlowerAccelerationDiffersFromTheHandWorkedReference) {
  const TranscriptResult r = run_transcript_text(
      "> MO=1\nwait 30ms\n> SP=50000;AC=900000;DC=1000000;PA=100000\n"
      "record DV[2],DV[3] trigger=begin length=8 gap=20\n> BG\nwait 10ms\nexpect first_steps.csv\n",
      "t.txt", kDir);
  ASSERT_EQ(r.failures.size(), 1u);
  // a = 9e5: DV[2] = 45 counts/s at the trigger sample, 50 in the reference.
  EXPECT_EQ(r.failures[0],
            "t.txt:7: expect first_steps.csv: DV[2] at 0.000 ms (sample 0): 45, expected 50 "
            "(tolerance 0)");
}

TEST(transcript_recorder, ATolerancePassesAndAMissingRecordingFails) {
  TranscriptResult r = run_transcript_text(
      "> MO=1\nwait 30ms\n> SP=50000;AC=900000;DC=1000000;PA=100000\n"
      "record DV[2],DV[3] trigger=begin length=8 gap=20\n> BG\nwait 10ms\nexpect first_steps.csv "
      "DV[2]=705 DV[3]=3\n",
      "t.txt", kDir);
  EXPECT_TRUE(r.ok) << (r.failures.empty() ? "" : r.failures[0]);
  r = run_transcript_text(
      "> MO=1\nrecord PX trigger=begin\nwait 1ms\nexpect first_steps.csv\nexpect nosuch.csv\n",
      "t.txt", kDir);
  ASSERT_EQ(r.failures.size(), 2u);
  EXPECT_EQ(r.failures[0],
            "t.txt:4: expect first_steps.csv: the recorder has not been triggered (is a 'record' "
            "line before it?)");
  EXPECT_NE(r.failures[1].find("t.txt:5: expect nosuch.csv: "), std::string::npos) << r.failures[1];
}

TEST(transcript_recorder, BadSettingsAreRefusedWithTheirReason) {
  const TranscriptResult r = run_transcript_file(kDir + "/bad_settings.txt");
  ASSERT_EQ(r.failures.size(), 4u);
  EXPECT_NE(r.failures[0].find(
                "bad_settings.txt:3: record: 'QQ' is no signal and no global of the program"),
            std::string::npos);
  EXPECT_NE(
      r.failures[1].find("bad_settings.txt:4: record: trigger 'sideways': expected immediate"),
      std::string::npos);
  EXPECT_NE(
      r.failures[2].find("bad_settings.txt:5: record: 'length=0' needs a whole number in range"),
      std::string::npos);
  EXPECT_NE(r.failures[3].find(
                "bad_settings.txt:6: record: 'pretrigger=101' needs a whole number in range"),
            std::string::npos);
}

}  // namespace
}  // namespace uprog::transcript
