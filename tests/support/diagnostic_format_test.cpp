// How a diagnostic is printed: its source line with a caret under the column, notes with their
// own lines, text that is not printable escaped, long lines windowed, errors beyond a limit
// counted, and JSON that stays valid whatever bytes the source held.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/diagnostic.h"
#include "testlib/terminal_text.h"

using namespace uprog;
using uprog::test::safe_for_terminal;

namespace {

Diagnostic error_at(const std::string& file, int line, int column, const std::string& message) {
  Diagnostic d;
  d.scheme = "gold";
  d.code = 12;
  d.message = message;
  d.where = {file, line, column};
  return d;
}

}  // namespace

TEST(diagnostic_format, TheLineAndACaretUnderTheColumnAsGccPrintsThem) {
  std::vector<Diagnostic> ds{error_at("p.gold", 12, 9, "No such variable 'y'")};
  std::string text;
  for (int i = 1; i < 12; ++i) text += "a = 1\n";
  text += "    x = y +\r\nz = 2\n";  // a CR LF line end is not part of the line
  attach_source_lines(ds, SourceFile{"p.gold", text});
  EXPECT_EQ(format_text(ds),
            "p.gold:12:9: error: No such variable 'y' [gold 12]\n"
            " 12 |     x = y +\n"
            "    |         ^\n");
}

TEST(diagnostic_format, TabsBeforeTheColumnStayTabsSoTheCaretLinesUp) {
  std::vector<Diagnostic> ds{error_at("t.gold", 1, 3, "x")};
  attach_source_lines(ds, SourceFile{"t.gold", "\t\tbad\n"});
  EXPECT_EQ(format_text(ds), "t.gold:1:3: error: x [gold 12]\n 1 | \t\tbad\n   | \t\t^\n");
}

TEST(diagnostic_format, ACaretPastTheEndOfTheLineAndNoCaretWithoutAColumn) {
  std::vector<Diagnostic> ds{error_at("e.gold", 1, 4, "end"),
                             error_at("e.gold", 2, 0, "no column")};
  attach_source_lines(ds, SourceFile{"e.gold", "a =\nb\n"});
  EXPECT_EQ(format_text(ds),
            "e.gold:1:4: error: end [gold 12]\n 1 | a =\n   |    ^\n"
            "e.gold:2: error: no column [gold 12]\n 2 | b\n");
}

TEST(diagnostic_format, OnlyTheFileTheDiagnosticNamesGivesItsLine) {
  // As through an #include: the diagnostic is in the included file, its note in the main one.
  Diagnostic d = error_at("inc.gold", 2, 5, "Value is expected");
  // Notes built by name: g++ 12 at -O3 warns falsely (maybe-uninitialized) of braced temporaries.
  DiagnosticNote included;
  included.where = {"main.gold", 1, 1};
  included.message = "included from here";
  d.notes.push_back(included);
  DiagnosticNote same_line;
  same_line.where = {"inc.gold", 2, 1};
  same_line.message = "on the diagnostic's own line: no second excerpt";
  d.notes.push_back(same_line);
  std::vector<Diagnostic> ds{d, error_at("other.gold", 1, 1, "another file")};
  attach_source_lines(ds, SourceFile{"main.gold", "#include \"inc.gold\"\n"});
  attach_source_lines(ds, SourceFile{"inc.gold", "int a\na = SPEED\n"});
  EXPECT_EQ(format_text(ds),
            "inc.gold:2:5: error: Value is expected [gold 12]\n"
            " 2 | a = SPEED\n"
            "   |     ^\n"
            "main.gold:1:1: note: included from here\n"
            " 1 | #include \"inc.gold\"\n"
            "   | ^\n"
            "inc.gold:2:1: note: on the diagnostic's own line: no second excerpt\n"
            "other.gold:1:1: error: another file [gold 12]\n");
}

TEST(diagnostic_format, ALineBeyondTheTextHasNoExcerpt) {
  std::vector<Diagnostic> ds{error_at("s.gold", 5, 1, "past the end")};
  attach_source_lines(ds, SourceFile{"s.gold", "one line\n"});
  EXPECT_FALSE(ds[0].line.has_value());
  EXPECT_EQ(format_text(ds), "s.gold:5:1: error: past the end [gold 12]\n");
}

TEST(diagnostic_format, UnprintableBytesAreEscapedInLineAndMessage) {
  // An escape sequence that would turn the terminal red, a NUL, DEL, a lone continuation byte,
  // a C1 control (U+009B, CSI) and a right-to-left override; valid UTF-8 text stays.
  const std::string line = std::string("a\x1b[31m\x00\x7f\x80", 9) +
                           "\xc2\x9b"
                           "\xe2\x80\xae"
                           "µs b";
  std::vector<Diagnostic> ds{
      error_at("bin", 1, static_cast<int>(line.size()), "unknown opcode '" + line + "'")};
  attach_source_lines(ds, SourceFile{"bin", line + "\n"});
  const std::string shown = format_text(ds);
  EXPECT_TRUE(safe_for_terminal(shown)) << shown;
  const std::string escaped = "a\\x1B[31m\\x00\\x7F\\x80\\xC2\\x9B\\xE2\\x80\\xAEµs b";
  EXPECT_EQ(shown, "bin:1:" + std::to_string(line.size()) + ": error: unknown opcode '" + escaped +
                       "' [gold 12]\n"
                       " 1 | " +
                       escaped +
                       "\n"
                       "   | " +
                       std::string(escaped.size() - 2, ' ') + "^\n");
}

TEST(diagnostic_format, ALongLineShowsAWindowAroundTheColumn) {
  std::string line(400, 'x');
  line[300] = 'Y';
  std::vector<Diagnostic> ds{error_at("long.gold", 1, 301, "here")};
  attach_source_lines(ds, SourceFile{"long.gold", line});
  ASSERT_TRUE(ds[0].line.has_value());
  const SourceLine& l = *ds[0].line;
  EXPECT_GT(l.first_column, 1);
  EXPECT_TRUE(l.cut_after);
  EXPECT_LE(l.text.size(), 160u);
  EXPECT_EQ(l.text[static_cast<size_t>(301 - l.first_column)], 'Y');
  const std::string shown = format_text(ds);
  const size_t source = shown.find(" 1 | ...");
  const size_t caret = shown.find("   | ", source);
  ASSERT_NE(source, std::string::npos) << shown;
  ASSERT_NE(caret, std::string::npos) << shown;
  // The caret is under the Y, counted from the start of each line.
  const size_t y = shown.find('Y', source) - source;
  EXPECT_EQ(shown.find('^', caret) - caret, y) << shown;
  EXPECT_NE(shown.find("...\n", source), std::string::npos) << "the cut after is marked";
}

TEST(diagnostic_format, ABinaryLineIsCutByWhatItShowsNotByItsBytes) {
  const std::string line(5000, '\0');
  std::vector<Diagnostic> ds{error_at("b", 1, 1, line)};
  attach_source_lines(ds, SourceFile{"b", line});
  const std::string shown = format_text(ds);
  size_t longest = 0;
  for (size_t b = 0, e; b < shown.size(); b = e + 1) {
    e = shown.find('\n', b);
    longest = std::max(longest, e - b);
  }
  EXPECT_LE(longest, 240u) << shown;
}

TEST(diagnostic_format, ErrorsBeyondTheLimitAreCountedNotShown) {
  std::vector<Diagnostic> ds;
  for (int i = 1; i <= 40; ++i) ds.push_back(error_at("a.s", i, 1, "unknown opcode"));
  Diagnostic note = error_at("a.s", 3, 1, "a note after the third error stays with it");
  note.severity = Severity::Note;
  ds.insert(ds.begin() + 3, note);
  limit_errors(ds, 30);
  ASSERT_EQ(ds.size(), 32u);
  EXPECT_EQ(ds[3].severity, Severity::Note);
  EXPECT_EQ(ds[30].where.line, 30);
  EXPECT_EQ(format_text(ds[31]), "a.s: note: 10 more errors not shown\n");
  limit_errors(ds, 30);
  EXPECT_EQ(ds.size(), 32u) << "within the limit nothing changes";
}

TEST(diagnostic_format, JsonCarriesTheLineAndStaysValidForAnyBytes) {
  std::vector<Diagnostic> ds{error_at("j.gold", 1, 2, std::string("bad \xff\x1b name"))};
  attach_source_lines(ds, SourceFile{"j.gold", std::string("a\xff\x1b\n")});
  const std::string json = format_json(ds);  // invalid UTF-8 would make the JSON writer throw
  const nlohmann::json parsed = nlohmann::json::parse(json);
  ASSERT_EQ(parsed.size(), 1u);
  EXPECT_EQ(parsed[0]["message"], "bad \\xFF\\x1B name");
  EXPECT_EQ(parsed[0]["source_line"], "a\\xFF\\x1B");
  EXPECT_EQ(parsed[0]["line"], 1);
  EXPECT_EQ(parsed[0]["column"], 2);
  EXPECT_EQ(parsed[0]["code"], 12);
  EXPECT_EQ(parsed[0]["scheme"], "gold");
  EXPECT_TRUE(parsed[0]["notes"].is_array());
}

TEST(diagnostic_format, NothingToAttachReadsNothing) {
  std::vector<Diagnostic> none;
  attach_source_lines(none, SourceFile{"x", "text"});
  EXPECT_TRUE(none.empty());
  std::vector<Diagnostic> no_line{error_at("x", 0, 0, "Open file failure")};
  attach_source_lines(no_line, SourceFile{"x", "text"});
  EXPECT_FALSE(no_line[0].line.has_value());
}
