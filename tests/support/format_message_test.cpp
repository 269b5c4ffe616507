// format_message() against C's printf, case by case (format_cases.txt), and its limits.
#include "support/format_message.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "testlib/test_files.h"

namespace uprog {
namespace {

// Reads a C-escaped "string" at `at`; advances past it.
std::string quoted(const std::string& line, size_t& at) {
  std::string s;
  EXPECT_EQ(line[at], '"') << line;
  for (++at; at < line.size() && line[at] != '"'; ++at) {
    if (line[at] != '\\') {
      s += line[at];
      continue;
    }
    const char e = line[++at];
    s += e == 'n' ? '\n' : e == 't' ? '\t' : e;
  }
  ++at;
  return s;
}

Value word(const std::string& token) {
  if (token[0] == 'f') return Value::of_float(std::stof(token.substr(1)));
  return Value::of_bits(static_cast<uint32_t>(std::stoll(token, nullptr, 0)));
}

TEST(FormatMessage, Cases) {
  std::istringstream lines(
      test::read_whole(std::string(UPROG_SOURCE_DIR) + "/tests/support/format_cases.txt"));
  int cases = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    size_t at = 0;
    const std::string format = quoted(line, at);
    const size_t arrow = line.find(" => ", at);
    ASSERT_NE(arrow, std::string::npos) << line;
    std::vector<Value> words;
    std::istringstream tokens(line.substr(at, arrow - at));
    for (std::string t; tokens >> t;) words.push_back(word(t));
    at = arrow + 4;
    const std::string expected = quoted(line, at);
    EXPECT_EQ(format_message(format, words.data(), words.size()), expected) << line;
    ++cases;
  }
  EXPECT_GT(cases, 40);
}

TEST(FormatMessage, WidthsAreCapped) {
  const Value one = Value::of_int(1);
  EXPECT_EQ(format_message("%99999999999d", &one, 1), std::string(kMaxFormatWidth - 1, ' ') + "1");
  const std::string wide = format_message("%.99999f", &one, 1);
  EXPECT_EQ(wide.size(), 2u + kMaxFormatWidth);  // "0." and the capped precision
}

TEST(FormatMessage, NoWordsAtAll) { EXPECT_EQ(format_message("%d|%s|%x", nullptr, 0), "0||0"); }

}  // namespace
}  // namespace uprog
