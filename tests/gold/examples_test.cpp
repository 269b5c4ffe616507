// Every program in examples/gold compiles without a diagnostic, and runs on the simulated drive
// as the transcript beside it (NAME.txt) says: for the manual's own examples (2_xx_*) the values
// the manual gives and what its text says the program does, for the others what their comments
// promise.
#include <gtest/gtest.h>

#include <filesystem>

#include "dialects/gold/compile.h"
#include "gold_runner.h"
#include "testlib/test_files.h"
#include "transcript/transcript.h"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> examples() { return uprog::test::source_files("examples/gold", ".ehl"); }

}  // namespace

TEST(gold_examples, AllCompileClean) {
  size_t n = 0;
  for (const fs::path& path : examples()) {
    ++n;
    const auto r = uprog::gold::compile(
        uprog::SourceFile{path.filename().string(), uprog::test::read_whole(path)});
    EXPECT_TRUE(r.diagnostics.empty()) << uprog::format_text(r.diagnostics);
    EXPECT_FALSE(r.image.code.empty()) << path;
    // The VM's verifier accepts what the compiler made.
    uprog::gold_test::GoldRun run;
    EXPECT_TRUE(run.load(r.image)) << path;
  }
  EXPECT_GE(n, 12u);
}

class GoldExample : public ::testing::TestWithParam<fs::path> {};

TEST_P(GoldExample, RunsAsItsTranscriptSays) {
  fs::path transcript = GetParam();
  transcript.replace_extension(".txt");
  ASSERT_TRUE(fs::exists(transcript)) << "no transcript beside " << GetParam().filename();
  const std::string text = uprog::test::read_whole(transcript);
  EXPECT_NE(text.find("load " + GetParam().filename().string() + "\n"), std::string::npos)
      << "the transcript must load its own example";
  const uprog::transcript::TranscriptResult r =
      uprog::transcript::run_transcript_file(transcript.string());
  for (const std::string& f : r.failures) ADD_FAILURE() << f;
  EXPECT_GE(r.checks, 3) << "a transcript that checks almost nothing proves almost nothing";
}

INSTANTIATE_TEST_SUITE_P(Examples, GoldExample, ::testing::ValuesIn(examples()),
                         [](const auto& param_info) { return param_info.param.stem().string(); });
