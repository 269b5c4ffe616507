// Every tests/pup/diagnostics/NAME.pup gives, as its first diagnostic, the line in NAME.expected
// ("file:line:col: error: text [pup N]", the file without its folder); and every registered
// [pup N] has such a case.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "dialects/pup/errors.h"
#include "dialects/pup/pup_compiler.h"
#include "support/files.h"

namespace uprog::pup {
namespace {

const std::filesystem::path kDir =
    std::filesystem::path(UPROG_SOURCE_DIR) / "tests/pup/diagnostics";

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(PupDiagnostics, EveryCaseGivesItsDiagnostic) {
  std::set<int> covered;
  for (const auto& entry : std::filesystem::directory_iterator(kDir)) {
    if (entry.path().extension() != ".pup") continue;
    const PupOutput out = compile_pup_file(entry.path().string(), 0);
    ASSERT_FALSE(out.diagnostics.empty()) << entry.path();
    std::string got = first_line(format_text(out.diagnostics.front()));
    const std::string folder = kDir.string() + "/";
    if (got.starts_with(folder)) got = got.substr(folder.size());
    std::filesystem::path expected = entry.path();
    expected.replace_extension(".expected");
    const auto text = read_text_file(expected.string());
    ASSERT_TRUE(text) << expected;
    EXPECT_EQ(got, first_line(*text)) << entry.path();
    if (out.diagnostics.front().scheme == "pup") covered.insert(out.diagnostics.front().code);
  }
  for (const dialect::ErrorInfo& e : diagnostic_table()) {
    EXPECT_TRUE(covered.count(e.code)) << "[pup " << e.code << "] " << e.name << " has no case";
  }
}

}  // namespace
}  // namespace uprog::pup
