// Runs every tests/preproc/cases/*.case: a source, the output the preprocessor must give and
// the diagnostics it must report. The file format is described in cases/README.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "preproc/preprocess.h"

namespace uprog::preproc {
namespace {

namespace fs = std::filesystem;

const fs::path kCaseDir = fs::path(UPROG_SOURCE_DIR) / "tests" / "preproc" / "cases";

struct Case {
  std::map<std::string, std::string> sections;  // "input", "output", "diagnostics", "options"
};

Case read_case(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  Case c;
  std::string line, current;
  while (std::getline(in, line)) {
    if (line.rfind("=== ", 0) == 0) {
      current = line.substr(4);
      c.sections[current];  // an empty section still exists
      continue;
    }
    if (!current.empty()) c.sections[current] += line + "\n";
  }
  return c;
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty()) out.push_back(line);
  }
  return out;
}

// "LINE:COL CODE TEXT", the way a case writes an expected diagnostic.
std::string brief(const Diagnostic& d) {
  return std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + " " +
         std::to_string(d.code) + " " + d.message;
}

PreprocOptions options_for(const std::string& spec) {
  PreprocOptions o;
  for (const std::string& word : lines_of(spec)) {
    if (word == "undefined_identifier_is_zero")
      o.undefined_identifier_is_zero = true;
    else if (word == "no_unknown_hash_lines")
      o.unknown_hash_lines_pass_through = false;
    else if (word == "allow_include")
      o.allow_include = true;
    else if (word == "allow_function_macros")
      o.allow_function_macros = true;
    else
      ADD_FAILURE() << "unknown option in case: " << word;
  }
  return o;
}

std::vector<fs::path> case_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kCaseDir)) {
    if (e.path().extension() == ".case") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class PreprocCase : public ::testing::TestWithParam<fs::path> {};

TEST_P(PreprocCase, GivesExpectedOutputAndDiagnostics) {
  const Case c = read_case(GetParam());
  ASSERT_TRUE(c.sections.count("input")) << "a case needs an === input section";
  ASSERT_TRUE(c.sections.count("output")) << "a case needs an === output section";
  const std::string& input = c.sections.at("input");
  const auto opt_it = c.sections.find("options");
  const PreprocOptions options = options_for(opt_it == c.sections.end() ? "" : opt_it->second);

  DiagnosticList diagnostics;
  const Preprocessed p = preprocess({"case.prg", input}, options, diagnostics);

  EXPECT_EQ(p.text, c.sections.at("output"));
  // Line numbers survive: one output line per input line.
  EXPECT_EQ(std::count(p.text.begin(), p.text.end(), '\n'),
            std::count(input.begin(), input.end(), '\n'));

  std::vector<std::string> got;
  for (const Diagnostic& d : diagnostics.items()) {
    EXPECT_EQ(d.scheme, "gold");
    EXPECT_EQ(d.where.file, "case.prg");
    got.push_back(brief(d));
  }
  const auto diag_it = c.sections.find("diagnostics");
  const std::vector<std::string> want =
      diag_it == c.sections.end() ? std::vector<std::string>{} : lines_of(diag_it->second);
  EXPECT_EQ(got, want);
}

INSTANTIATE_TEST_SUITE_P(preproc, PreprocCase, ::testing::ValuesIn(case_files()),
                         [](const ::testing::TestParamInfo<fs::path>& param_info) {
                           std::string name = param_info.param.stem().string();
                           for (char& ch : name) {
                             if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

// Every preprocessor code of Gold's table has a case that produces it.
TEST(preproc_cases, EveryGoldCodeHasACase) {
  std::set<int> seen;
  for (const fs::path& f : case_files()) {
    const Case c = read_case(f);
    const auto it = c.sections.find("diagnostics");
    if (it == c.sections.end()) continue;
    for (const std::string& line : lines_of(it->second)) {
      std::istringstream in(line);
      std::string place;
      int code = 0;
      in >> place >> code;
      seen.insert(code);
    }
  }
  for (int code : {86, 87, 88, 89, 90, 92, 93, 94, 95, 96}) {
    EXPECT_TRUE(seen.count(code)) << "no case produces Gold error " << code;
  }
  EXPECT_GE(case_files().size(), 30u);
}

}  // namespace
}  // namespace uprog::preproc
