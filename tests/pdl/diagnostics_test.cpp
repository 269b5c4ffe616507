// PDL's diagnostics as data: every case of tests/diagnostics/pdl/cases.txt compiled must give
// exactly its listed `line:col code` diagnostics, and every registered code has a case.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "dialects/pdl/compile.h"
#include "dialects/pdl/errors.h"

namespace fs = std::filesystem;
using namespace uprog;

namespace {

struct Case {
  std::string name;
  std::string source;
  std::vector<std::string> expected;  // "line:col code"
};

// "### name", the source, "---", the expected diagnostics, up to the next "###".
std::vector<Case> read_cases() {
  std::ifstream in(fs::path(UPROG_SOURCE_DIR) / "tests/diagnostics/pdl/cases.txt");
  std::vector<Case> out;
  bool in_expected = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("### ")) {
      out.push_back({line.substr(4), "", {}});
      in_expected = false;
    } else if (out.empty()) {
      continue;
    } else if (line == "---") {
      in_expected = true;
    } else if (in_expected) {
      if (!line.empty()) out.back().expected.push_back(line);
    } else {
      out.back().source += line + "\n";
    }
  }
  return out;
}

// A case compiles as if it were a file beside cases.txt, so that `#include "include/x.pdh"`
// finds tests/diagnostics/pdl/include/x.pdh; a diagnostic in an included file is listed as
// `x.pdh:line:col code`.
std::vector<std::string> got(const Case& c) {
  const std::string name = (fs::path(UPROG_SOURCE_DIR) / "tests/diagnostics/pdl/case.pdl").string();
  const pdl::CompileResult r = pdl::compile(SourceFile{name, c.source});
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics) {
    if (d.severity == Severity::Note) continue;
    const std::string file =
        d.where.file == name ? "" : fs::path(d.where.file).filename().string() + ":";
    out.push_back(file + std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + " " +
                  std::to_string(d.code));
  }
  return out;
}

TEST(PdlDiagnostics, EveryCaseGivesItsDiagnostics) {
  const std::vector<Case> cases = read_cases();
  ASSERT_GT(cases.size(), 40u);
  for (const Case& c : cases) {
    EXPECT_EQ(got(c), c.expected) << "case: " << c.name;
  }
}

TEST(PdlDiagnostics, EveryRegisteredCodeHasACase) {
  std::set<int> seen;
  for (const Case& c : read_cases()) {
    for (const std::string& e : c.expected) seen.insert(std::stoi(e.substr(e.find(' ') + 1)));
  }
  size_t count = 0;
  const pdl::ErrorEntry* all = pdl::all_errors(count);
  for (size_t i = 0; i < count; ++i)
    EXPECT_TRUE(seen.count(all[i].code))
        << "no case gives [pdl " << all[i].code << "] " << all[i].name;
}

TEST(PdlDiagnostics, PrintedAsGccDoes) {
  const pdl::CompileResult r = pdl::compile(SourceFile{"f.pdl", "#long a\nb = 1;\n"});
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(format_text(r.diagnostics[0]).substr(0, 43),
            "f.pdl:2:1: error: unknown name: b [pdl 20]\n");
}

TEST(PdlDiagnostics, ACleanProgramHasNone) {
  const pdl::CompileResult r =
      pdl::compile(SourceFile{"f.pdl", "#long a\n#task/1;\na = 1;\nhalt;\n"});
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_TRUE(r.ok());
  EXPECT_FALSE(r.image.code.empty());
}

}  // namespace
