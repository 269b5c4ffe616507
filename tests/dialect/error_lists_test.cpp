// Every registered dialect's interpreter error list (its interpreter_errors.def, in one form:
// EC(CODE, NAME, "text")) against the transcripts: each list is well formed, every code a
// transcript of the dialect expects (`! CODE`) is in its list, and every code in its list is
// expected by a transcript of the dialect, unless it is exempt below with the reason no host line
// can produce it today.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>

#include "dialects/registry.h"
#include "testlib/test_files.h"

namespace uprog::dialect {
namespace {

namespace fs = std::filesystem;

// Codes no transcript produces, per dialect, each with the reason. A code leaves this table when
// a transcript produces it: the test fails while both hold.
const std::map<std::string, std::map<int32_t, std::string>> kNotFromATranscript = {
    {"gold",
     {{5, "the compiler refuses it first (tests/interpreter_errors/error_transcripts_test.cpp)"},
      {23, "the compiler refuses it first (error_transcripts_test.cpp)"},
      {43, "the compiler refuses it first (error_transcripts_test.cpp)"},
      {64, "a persistent fault cause, which `fault` cannot latch (error_transcripts_test.cpp)"},
      {103, "a line calls no function (error_transcripts_test.cpp)"},
      {104, "a line calls no function"},
      {106, "a refused drive command answers with the drive's own code instead"},
      {107, "a line holds one block"},
      {108, "try and catch stand on lines of their own"},
      {109, "the compiler never ends a try block it did not enter"},
      {110, "a line's routine takes no inputs"},
      {111, "a line runs on thread 0 of its own machine"},
      {112, "a line's image always has its one routine"},
      {113, "no event enters a line's machine"},
      {114, "no Gold statement raises an error"},
      {115, "Gold has no pointers"},
      {117, "Gold calls no intrinsic function (INTRIN)"}}},
    {"pdl",
     {{12,
       "no host line makes the simulated axis refuse an enable today: with `fault feedback` "
       "latched, X_enable=1 is still accepted"}}},
    {"pup",
     {{14,
       "only the loader's refusal of a CUP that uses such a keyword in a program (cup_loader.cpp, "
       "a download's 45) says it; the compiler refuses it first"},
      {26,
       "a program thread's error, checked as AProgError's value "
       "(pup/stack_errors_at_run_time.txt); no transcript fills thread 0's stack from the host"},
      {28, "a program thread's error (AProgError, AErrLog), not a host line's answer"},
      {29, "a program thread's error (AProgError, AErrLog), not a host line's answer"},
      {34, "no transcript sets a 17th breakpoint yet (program_control.cpp keeps 16)"},
      {46, "only a flash write that fails, which a transcript cannot make"}}},
    {"st",
     {{10,
       "only a flash write that fails (PLCDL END, SAVE), which a transcript cannot make: an "
       "oversized source is refused at PLCDL BEGIN (13)"}}},
};

// The dialect a transcript runs on: its `dialect NAME` line, else the registry's default.
std::string dialect_of(const std::string& text) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("dialect ", 0) == 0) {
      std::string name = line.substr(8);
      name.erase(name.find_last_not_of(" \t\r") + 1);
      return name.substr(0, name.find_first_of(" \t#"));
    }
  }
  return std::string(dialects::default_dialect().name());
}

// Every `! CODE` of every transcript in the tree, by dialect.
std::map<std::string, std::set<int32_t>> expected_codes() {
  std::map<std::string, std::set<int32_t>> codes;
  for (const char* root : {"tests/transcripts", "examples"}) {
    for (const auto& e : fs::recursive_directory_iterator(fs::path(UPROG_SOURCE_DIR) / root)) {
      if (!e.is_regular_file() || e.path().extension() != ".txt" ||
          e.path().filename() == "CMakeLists.txt")
        continue;
      const std::string text = test::read_whole(e.path());
      std::set<int32_t>& mine = codes[dialect_of(text)];
      std::istringstream lines(text);
      for (std::string line; std::getline(lines, line);) {
        const size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos || line[start] != '!') continue;
        std::istringstream rest(line.substr(start + 1));
        int32_t code = 0;
        if (rest >> code) mine.insert(code);
      }
    }
  }
  return codes;
}

TEST(ErrorLists, EachIsWellFormed) {
  for (const Dialect* d : dialects::all()) {
    std::set<int32_t> seen;
    for (const ErrorInfo& e : d->interpreter_errors()) {
      EXPECT_TRUE(seen.insert(e.code).second) << d->name() << " lists " << e.code << " twice";
      EXPECT_GT(e.code, 0) << d->name();
      EXPECT_FALSE(e.name.empty()) << d->name() << " " << e.code;
      EXPECT_FALSE(e.text.empty()) << d->name() << " " << e.code;
    }
  }
}

TEST(ErrorLists, EveryCodeATranscriptExpectsIsRegistered) {
  const auto expected = expected_codes();
  for (const Dialect* d : dialects::all()) {
    const auto it = expected.find(std::string(d->name()));
    if (it == expected.end()) continue;
    std::set<int32_t> listed;
    for (const ErrorInfo& e : d->interpreter_errors()) listed.insert(e.code);
    for (int32_t code : it->second) {
      EXPECT_TRUE(listed.count(code) != 0)
          << d->name() << ": a transcript expects ! " << code
          << ", which its interpreter error list does not register";
    }
  }
}

TEST(ErrorLists, EveryRegisteredCodeIsProducedByATranscriptOrExempt) {
  const auto expected = expected_codes();
  for (const Dialect* d : dialects::all()) {
    const std::string name(d->name());
    const auto produced = expected.find(name);
    const auto exempt = kNotFromATranscript.find(name);
    for (const ErrorInfo& e : d->interpreter_errors()) {
      const bool is_produced = produced != expected.end() && produced->second.count(e.code) != 0;
      const bool is_exempt =
          exempt != kNotFromATranscript.end() && exempt->second.count(e.code) != 0;
      EXPECT_TRUE(is_produced || is_exempt)
          << name << " " << e.code << " (" << e.name << "): no transcript expects it";
      EXPECT_FALSE(is_produced && is_exempt)
          << name << " " << e.code << " is produced now: take it out of kNotFromATranscript";
    }
  }
}

}  // namespace
}  // namespace uprog::dialect
