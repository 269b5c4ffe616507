// What a file that is no Gold program gives: a real binary (this test's own executable) and a
// text with an error on every line. At most CompileOptions::max_errors errors and "Too many
// errors" (46), found in bounded time, every byte of the output printable.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>

#include "dialects/gold/compile.h"
#include "testlib/terminal_text.h"

using namespace uprog;

namespace {

std::string own_executable(size_t max_bytes) {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  std::string bytes(max_bytes, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<size_t>(in.gcount()));
  return bytes;
}

gold::CompileResult check(const std::string& name, std::string text) {
  gold::CompileOptions options;
  options.check_only = true;
  return gold::compile(SourceFile{name, std::move(text)}, options);
}

}  // namespace

TEST(gold_binary_input, AnExecutableGivesBoundedEscapedDiagnostics) {
  const std::string bytes = own_executable(4 << 20);
  ASSERT_GT(bytes.size(), 100000u);
  ASSERT_EQ(bytes.substr(0, 4),
            "\x7f"
            "ELF");
  const gold::CompileResult r = check("a.out", bytes);
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), gold::CompileOptions{}.max_errors + 1);
  EXPECT_EQ(r.diagnostics.back().code, 46);
  const std::string shown = format_text(r.diagnostics);
  EXPECT_TRUE(test::safe_for_terminal(shown));
  EXPECT_NE(shown.find(" 1 | \\x7FELF"), std::string::npos) << "the first line, escaped";
  for (const Diagnostic& d : r.diagnostics) EXPECT_TRUE(d.line.has_value()) << format_text(d);
}

// An error on each of 200 000 lines: collecting them all (and looking for a duplicate among them
// for each new one) took quadratic time; the compiler stops once it holds enough to show.
TEST(gold_binary_input, AnErrorOnEveryLineIsFoundInBoundedTime) {
  std::string text = "function f()\n";
  for (int i = 0; i < 200000; ++i) text += "x = )\n";
  text += "return\n";
  const auto start = std::chrono::steady_clock::now();
  const gold::CompileResult r = check("many.gold", text);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0);
  ASSERT_EQ(r.diagnostics.size(), 31u);
  // The first 30 by place, as without the bound: "Value is expected" at each ')' from line 2.
  for (int i = 0; i < 30; ++i) {
    EXPECT_EQ(r.diagnostics[static_cast<size_t>(i)].where.line, i + 2);
    EXPECT_EQ(r.diagnostics[static_cast<size_t>(i)].code, 7);
  }
  EXPECT_EQ(r.diagnostics[30].code, 46);
  EXPECT_EQ(r.diagnostics[30].where.line, 32);
}
