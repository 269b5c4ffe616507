// Every transcript in tests/transcripts/debug, replayed with the debugger's directives, one
// case (and ctest) per file.
#include <gtest/gtest.h>

#include <filesystem>

#include "debug/transcript_debugger.h"
#include "testlib/test_files.h"

namespace uprog::debug {
namespace {

// One case per file, so that a failure names its transcript.
class DebugTranscript : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(DebugTranscript, Passes) {
  TranscriptDebugger extension;
  const transcript::TranscriptResult r =
      transcript::run_transcript_file(GetParam().string(), {}, nullptr, &extension);
  EXPECT_TRUE(r.ok);
  EXPECT_GT(r.checks, 0);
  for (const std::string& f : r.failures) ADD_FAILURE() << f;
}

INSTANTIATE_TEST_SUITE_P(Every, DebugTranscript,
                         ::testing::ValuesIn(test::source_files("tests/transcripts/debug", ".txt")),
                         [](const auto& param_info) { return param_info.param.stem().string(); });

TEST(DebugTranscripts, WithoutTheDebuggerTheDirectiveIsUnknown) {
  const auto r = transcript::run_transcript_text("debug attach\n", "t", ".");
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_NE(r.failures[0].find("unknown directive 'debug'"), std::string::npos);
}

}  // namespace
}  // namespace uprog::debug
