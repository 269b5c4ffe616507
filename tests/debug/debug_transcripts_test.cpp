// Every transcript in tests/transcripts/debug, replayed with the debugger's directives.
#include <gtest/gtest.h>

#include <filesystem>

#include "debug/transcript_debugger.h"

namespace uprog::debug {
namespace {

TEST(DebugTranscripts, EveryOnePasses) {
  const std::filesystem::path dir = UPROG_SOURCE_DIR "/tests/transcripts/debug";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    ++files;
    TranscriptDebugger extension;
    const transcript::TranscriptResult r =
        transcript::run_transcript_file(entry.path().string(), {}, nullptr, &extension);
    EXPECT_TRUE(r.ok) << entry.path();
    EXPECT_GT(r.checks, 0) << entry.path();
    for (const std::string& f : r.failures) ADD_FAILURE() << f;
  }
  EXPECT_GT(files, 0);
}

TEST(DebugTranscripts, WithoutTheDebuggerTheDirectiveIsUnknown) {
  const auto r = transcript::run_transcript_text("debug attach\n", "t", ".");
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_NE(r.failures[0].find("unknown directive 'debug'"), std::string::npos);
}

}  // namespace
}  // namespace uprog::debug
