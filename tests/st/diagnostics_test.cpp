// Runs every case in tests/diagnostics/st: NN_name.st compiled must print exactly the error
// lines of NN_name.expected, its first error must have code NN, and every registered code has
// a case (6, a source over 61 440 bytes, is made here).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "dialects/st/compile.h"
#include "dialects/st/errors.h"

namespace fs = std::filesystem;
using namespace uprog;

namespace {

const fs::path kDir = fs::path(UPROG_SOURCE_DIR) / "tests/diagnostics/st";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string error_lines(const std::vector<Diagnostic>& ds) {
  std::string out;
  for (const Diagnostic& d : ds) {
    Diagnostic bare = d;
    bare.line.reset();
    bare.notes.clear();
    out += format_text(bare);
  }
  return out;
}

}  // namespace

TEST(st_diagnostics, EveryCasePrintsItsExpectedErrors) {
  std::set<int> covered;
  size_t cases = 0;
  for (const auto& entry : fs::directory_iterator(kDir)) {
    const fs::path src = entry.path();
    if (src.extension() != ".st") continue;
    ++cases;
    SCOPED_TRACE(src.filename().string());
    fs::path expected = src;
    expected.replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected));
    const st::CompileResult r = st::compile(SourceFile{src.filename().string(), slurp(src)});
    EXPECT_EQ(error_lines(r.diagnostics), slurp(expected));
    const int code = std::stoi(src.filename().string().substr(0, 2));
    ASSERT_FALSE(r.diagnostics.empty());
    bool has_code = false;
    for (const Diagnostic& d : r.diagnostics) has_code |= d.code == code && d.scheme == "st";
    EXPECT_TRUE(has_code) << "no [st " << code << "]";
    covered.insert(code);
  }
  EXPECT_GT(cases, 40u);
  size_t count = 0;
  const st::ErrorInfo* all = st::all_errors(count);
  for (size_t i = 0; i < count; ++i) {
    if (all[i].code == static_cast<int>(st::Error::SourceTooLong)) continue;  // below
    EXPECT_TRUE(covered.count(all[i].code))
        << "no case for [st " << all[i].code << "] " << all[i].name;
  }
}

TEST(st_diagnostics, SourceOver61440BytesIsError6) {
  std::string text = "LONG A;\nPROGRAM PLCMAIN\n";
  while (text.size() <= st::kMaxSourceBytes) text += "  A := A + 1;\n";
  text += "END_PROGRAM\n";
  const st::CompileResult r = st::compile(SourceFile{"big.st", text});
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].code, 6);
  EXPECT_EQ(r.diagnostics[0].where.line, 1);
  // Exactly at the limit it compiles.
  std::string fits = "LONG A;\nPROGRAM PLCMAIN\nEND_PROGRAM\n";
  while (fits.size() + 10 <= st::kMaxSourceBytes) fits.insert(0, "// filler\n");
  fits.insert(0, st::kMaxSourceBytes - fits.size(), '\n');
  ASSERT_EQ(fits.size(), st::kMaxSourceBytes);
  EXPECT_TRUE(st::compile(SourceFile{"fits.st", fits}).ok());
}

TEST(st_diagnostics, SizesCountCodeLinesAndCalledFunctionsOnce) {
  const std::string text =
      "LONG A;\n"
      "FUNCTION F\n  A := 1;\n  A := 2;\nEND_FUNCTION\n"
      "PROGRAM PLC4\n"
      "  // a comment is no code\n"
      "  IF A THEN\n    FUNCTION (F);\n  ELSE\n    FUNCTION (F);\n  END_IF;\n"
      "END_PROGRAM\n";
  const st::CompileResult r = st::compile(SourceFile{"s.st", text});
  ASSERT_TRUE(r.ok()) << format_text(r.diagnostics);
  ASSERT_EQ(r.sizes.sizes.size(), 1u);
  EXPECT_EQ(r.sizes.sizes[0].name, "PLC4");
  EXPECT_EQ(r.sizes.sizes[0].size, 5u);  // IF, two calls, F's two lines once
  EXPECT_EQ(r.sizes.load, 20u);
  // The image carries the task record with its period.
  ASSERT_EQ(r.image.tasks.size(), 1u);
  EXPECT_EQ(r.image.tasks[0].period_ns, 4'000'000u);
  EXPECT_EQ(r.image.dialect, "st");
}

// #IFDEF finds a variable only below its declaration, as a #DEFINE only below its own (issue
// 39): B is declared after the program, so its block is skipped and PLCINIT has one line.
TEST(st_diagnostics, IfdefSeesOnlyVariablesDeclaredAbove) {
  const std::string text =
      "LONG A;\n"
      "PROGRAM PLCINIT\n"
      "  A := 1;\n"
      "#IFDEF B\n  A := 2;\n#ENDIF\n"
      "#IFDEF A\n  A := 3;\n#ENDIF\n"
      "END_PROGRAM\n"
      "LONG B;\n";
  const st::CompileResult r = st::compile(SourceFile{"p.st", text});
  ASSERT_TRUE(r.ok()) << format_text(r.diagnostics);
  EXPECT_EQ(r.sizes.sizes[0].size, 2u);  // A := 1 and A := 3
}

TEST(st_diagnostics, IfReadsDriveParametersAtCompileTime) {
  const std::string text =
      "LONG A;\n"
      "PROGRAM PLCINIT\n"
      "#IF PGEARI = 10000\n  A := 1;\n#ELSE\n  A := 2;\n  A := 3;\n#ENDIF\n"
      "#IFDEF A\n  A := A + 10;\n#ENDIF\n"
      "#IFDEF NOSUCH\n  A := 99;\n#ENDIF\n"
      "END_PROGRAM\n";
  const st::CompileResult defaults = st::compile(SourceFile{"p.st", text});
  ASSERT_TRUE(defaults.ok()) << format_text(defaults.diagnostics);
  EXPECT_EQ(defaults.sizes.sizes[0].size, 2u);  // the skipped lines are no code
  st::CompileOptions options;
  options.parameter = [](std::string_view name) -> std::optional<int32_t> {
    return name == "PGEARI" ? std::optional<int32_t>(4096) : std::nullopt;
  };
  const st::CompileResult other = st::compile(SourceFile{"p.st", text}, options);
  ASSERT_TRUE(other.ok());
  EXPECT_EQ(other.sizes.sizes[0].size, 3u);
}

// Error 25's note says why a parameter the drive knows cannot be read or written by XREAD or
// XWRITE (the spec: XREAD/XWRITE "go through the ASCII interpreter"; PFB is read-only, EN a
// command, ERRCODE a text), and names an unknown one alone.
TEST(st_diagnostics, Error25SaysWhyAKnownParameterIsRefused) {
  const std::string text = slurp(kDir / "25_unknown_parameter.st") +
                           "PROGRAM PLCINIT\n  XREAD('EN', A);\n"
                           "  XREAD('ERRCODE', A);\nEND_PROGRAM\n";
  const st::CompileResult r = st::compile(SourceFile{"x.st", text});
  std::vector<std::string> notes;
  for (const Diagnostic& d : r.diagnostics)
    if (d.code == 25 && !d.notes.empty()) notes.push_back(d.notes[0].message);
  EXPECT_EQ(notes, (std::vector<std::string>{"'NOSUCH'", "'PFB' is read-only", "'FLY'",
                                             "'EN' is a command (COMMAND runs it)",
                                             "'ERRCODE' answers text, not a number"}));
}
