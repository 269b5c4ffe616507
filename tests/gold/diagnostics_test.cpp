// Runs every case in tests/diagnostics/gold: NN_name.gold compiled must print exactly
// NN_name.expected. Also: every code the manual illustrates has a case, and each case
// produces the code its name announces.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "dialects/gold/compile.h"
#include "dialects/gold/errors.h"

namespace fs = std::filesystem;
using namespace uprog;

namespace {

const fs::path kDir = fs::path(UPROG_SOURCE_DIR) / "tests/diagnostics/gold";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<fs::path> cases() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(kDir))
    if (e.path().extension() == ".gold") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

int case_code(const fs::path& p) { return std::stoi(p.filename().string().substr(0, 2)); }

}  // namespace

TEST(gold_diagnostics, EveryCasePrintsItsExpectedOutput) {
  const auto all = cases();
  ASSERT_GT(all.size(), 60u);
  for (const fs::path& src : all) {
    SCOPED_TRACE(src.filename().string());
    fs::path expected = src;
    expected.replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected)) << "no .expected beside the case";
    const gold::CompileResult r = gold::compile(SourceFile{src.filename().string(), slurp(src)});
    EXPECT_EQ(format_text(r.diagnostics), slurp(expected));
    EXPECT_FALSE(r.ok());
  }
}

TEST(gold_diagnostics, EachCaseProducesTheCodeInItsName) {
  for (const fs::path& src : cases()) {
    SCOPED_TRACE(src.filename().string());
    const int code = case_code(src);
    const gold::CompileResult r = gold::compile(SourceFile{src.filename().string(), slurp(src)});
    bool found = false;
    for (const Diagnostic& d : r.diagnostics) found = found || (d.scheme == "gold" && d.code == code);
    EXPECT_TRUE(found) << "the case does not produce gold " << code;
  }
}

TEST(gold_diagnostics, EveryIllustratedCodeHasACase) {
  std::set<int> covered;
  for (const fs::path& src : cases()) covered.insert(case_code(src));
  size_t count = 0;
  const gold::ErrorInfo* errors = gold::all_errors(count);
  ASSERT_EQ(count, 98u);  // codes 0..97
  for (size_t i = 0; i < count; ++i) {
    EXPECT_EQ(errors[i].code, static_cast<int>(i)) << "the list is in code order, without gaps";
    if (errors[i].illustrated) {
      EXPECT_TRUE(covered.count(errors[i].code)) << "no case for gold " << errors[i].code;
    }
  }
}

TEST(gold_diagnostics, JsonFormIsAvailable) {
  const gold::CompileResult r = gold::compile(SourceFile{"x.gold", "##START\nBG=10\n"});
  const std::string json = format_json(r.diagnostics);
  EXPECT_NE(json.find("\"code\": 82"), std::string::npos) << json;
}

TEST(gold_diagnostics, MissingFileIsOpenFileFailure) {
  const gold::CompileResult r = gold::compile_file("/nonexistent/dir/prog.ehl");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, 54);
}
