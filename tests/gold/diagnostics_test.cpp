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

// A line of the excerpt under a diagnostic (" 12 | a = b +" or "    |     ^"), not a diagnostic.
bool is_excerpt_line(std::string_view line) {
  const size_t bar = line.find(" | ");
  if (line.empty() || line[0] != ' ' || bar == std::string_view::npos) return false;
  return line.substr(0, bar).find_first_not_of(" 0123456789") == std::string_view::npos;
}

bool shows_excerpts(const std::string& expected) {
  std::istringstream in(expected);
  for (std::string line; std::getline(in, line);)
    if (is_excerpt_line(line)) return true;
  return false;
}

std::string without_excerpts(std::vector<Diagnostic> ds) {
  for (Diagnostic& d : ds) {
    d.line.reset();
    for (DiagnosticNote& n : d.notes) n.line.reset();
  }
  return format_text(ds);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

// The .expected files hold the diagnostics' own lines. The source line and caret under each are
// compared where a case's .expected shows them, and checked against the source by rule for every
// case (EveryExcerptShowsTheLineAndColumnItNames).
TEST(gold_diagnostics, EveryCasePrintsItsExpectedOutput) {
  const auto all = cases();
  ASSERT_GT(all.size(), 60u);
  for (const fs::path& src : all) {
    SCOPED_TRACE(src.filename().string());
    fs::path expected = src;
    expected.replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected)) << "no .expected beside the case";
    const gold::CompileResult r = gold::compile(SourceFile{src.filename().string(), slurp(src)});
    const std::string want = slurp(expected);
    EXPECT_EQ(shows_excerpts(want) ? format_text(r.diagnostics) : without_excerpts(r.diagnostics),
              want);
    EXPECT_FALSE(r.ok());
  }
}

// Under every diagnostic and every note on a line of its own: the line of the case it names,
// then a caret under its column, in gcc's form. Computed here from the case's text alone.
TEST(gold_diagnostics, EveryExcerptShowsTheLineAndColumnItNames) {
  size_t excerpts = 0;
  for (const fs::path& src : cases()) {
    SCOPED_TRACE(src.filename().string());
    const std::string name = src.filename().string();
    const std::string text = slurp(src);
    const std::vector<std::string> source = lines_of(text);
    const gold::CompileResult r = gold::compile(SourceFile{name, text});
    auto excerpt = [&](const Location& w) {
      const std::string& line = source[static_cast<size_t>(w.line - 1)];
      EXPECT_EQ(line.find_first_of("\t\r"), std::string::npos) << "the cases are plain ASCII lines";
      const std::string number = std::to_string(w.line);
      return " " + number + " | " + line + "\n " + std::string(number.size(), ' ') + " | " +
             std::string(static_cast<size_t>(w.column - 1), ' ') + "^\n";
    };
    for (const Diagnostic& d : r.diagnostics) {
      const std::string shown = format_text(d);
      const bool in_case = d.where.file == name && d.where.line >= 1 &&
                           d.where.line <= static_cast<int>(source.size()) && d.where.column >= 1;
      EXPECT_EQ(d.line.has_value(), in_case) << shown;
      if (!in_case) continue;
      const std::string header = shown.substr(0, shown.find('\n') + 1);
      EXPECT_EQ(shown.substr(header.size(), excerpt(d.where).size()), excerpt(d.where)) << shown;
      ++excerpts;
      for (const DiagnosticNote& n : d.notes) {
        const bool own_line = n.where.line != d.where.line;
        EXPECT_EQ(n.line.has_value(), own_line) << shown;
        if (own_line) {
          EXPECT_NE(shown.find(": note: " + n.message + "\n" + excerpt(n.where)), std::string::npos)
              << shown;
        }
      }
    }
  }
  EXPECT_GT(excerpts, 90u);
}

TEST(gold_diagnostics, EachCaseProducesTheCodeInItsName) {
  for (const fs::path& src : cases()) {
    SCOPED_TRACE(src.filename().string());
    const int code = case_code(src);
    const gold::CompileResult r = gold::compile(SourceFile{src.filename().string(), slurp(src)});
    bool found = false;
    for (const Diagnostic& d : r.diagnostics)
      found = found || (d.scheme == "gold" && d.code == code);
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
