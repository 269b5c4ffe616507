// Replays every transcript in tests/transcripts/errors, and fails for any code of
// src/dialects/gold/interpreter_errors.def that none of them expects (`! CODE`), unless the code
// is exempt below with the reason no host line can produce it today.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "dialects/gold/dialect.h"
#include "testlib/test_files.h"
#include "transcript/transcript.h"

namespace uprog::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> error_transcripts() {
  return source_files("tests/transcripts/errors", ".txt");
}

// The codes no host line can produce today, each with the reason. A code leaves this table
// when a transcript produces it: the coverage test fails while both hold.
const std::map<int32_t, const char*> kNotFromAHostLine = {
    {5,
     "the compiler refuses reading an action (gold 7) or a host-only command (gold 79) first: 19"},
    {23, "the compiler refuses assigning an action first (gold 82): 19"},
    {43, "the compiler refuses assigning a status first (gold 82): 19"},
    {64,
     "needs a persistent fault cause, which a transcript's `fault` cannot latch "
     "(list_matches_enums_test.cpp produces it through the Controller's API)"},
    {103,
     "a line calls no function, and an expression too deep for the stack does not compile (gold "
     "3)"},
    {104, "a line calls no function"},
    {106, "a refused drive command answers with the drive's own code (2..65) instead"},
    {107,
     "a line holds one block (nested blocks are gold 43), at most two temporaries in 64 locals"},
    {108, "try and catch stand on lines of their own (gold 85); a host line is one line"},
    {109, "the compiler never ends a try block it did not enter"},
    {110, "a line's routine takes no inputs; XQ##f with wrong arguments is 205"},
    {111, "a line runs on thread 0 of its own machine"},
    {112, "a line's image always has its one routine"},
    {113, "no event enters a line's machine"},
    {114, "no Gold statement raises an error"},
    {115, "Gold has no pointers: its code generator emits no LDM or STM"},
    {116, "Gold has no MULDIV: its code generator emits none"},
    {117, "Gold calls no intrinsic function (INTRIN): its code generator emits none"},
};

class ErrorTranscript : public ::testing::TestWithParam<fs::path> {};

TEST_P(ErrorTranscript, Passes) {
  const transcript::TranscriptResult r = transcript::run_transcript_file(GetParam().string());
  for (const std::string& f : r.failures) ADD_FAILURE() << f;
  EXPECT_GT(r.checks, 0);
}

INSTANTIATE_TEST_SUITE_P(Files, ErrorTranscript, ::testing::ValuesIn(error_transcripts()),
                         [](const auto& param_info) { return param_info.param.stem().string(); });

TEST(ErrorTranscripts, ExpectEveryRegisteredCode) {
  std::set<int32_t> expected;
  const std::regex error_line(R"(\s*!\s*(\d+).*)");
  for (const fs::path& f : error_transcripts()) {
    std::istringstream lines(read_whole(f));
    std::smatch m;
    for (std::string line; std::getline(lines, line);)
      if (std::regex_match(line, m, error_line)) expected.insert(std::stoi(m[1]));
  }
  std::set<int32_t> registered;
  for (const dialect::ErrorInfo& e : gold::dialect().interpreter_errors()) {
    registered.insert(e.code);
    if (kNotFromAHostLine.count(e.code)) {
      EXPECT_FALSE(expected.count(e.code))
          << e.code << " (" << e.name << ") is produced now: drop its exemption";
    } else {
      EXPECT_TRUE(expected.count(e.code)) << "no transcript in tests/transcripts/errors produces "
                                          << e.code << " (" << e.name << ")";
    }
  }
  for (int32_t code : expected)
    EXPECT_TRUE(registered.count(code)) << code << " is expected but not registered";
  for (const auto& [code, why] : kNotFromAHostLine)
    EXPECT_TRUE(registered.count(code))
        << "exempt " << code << " is not registered (" << why << ")";
}

}  // namespace
}  // namespace uprog::test
