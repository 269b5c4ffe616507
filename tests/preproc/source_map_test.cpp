// SourceMap::locate: every output offset maps to the file, line and column the user wrote;
// inside an expansion, to the identifier that was replaced.
#include <gtest/gtest.h>

#include <string>

#include "preproc/preprocess.h"

namespace uprog::preproc {
namespace {

Preprocessed run(const std::string& text, DiagnosticList& d) {
  return preprocess({"m.prg", text}, PreprocOptions{}, d);
}

TEST(preproc_source_map, PlainTextMapsOneToOne) {
  DiagnosticList d;
  const std::string src = "ab\ncd\n\nef";
  const Preprocessed p = run(src, d);
  ASSERT_EQ(p.text, src);
  const Location l = p.map.locate(4);  // 'd'
  EXPECT_EQ(l.file, "m.prg");
  EXPECT_EQ(l.line, 2);
  EXPECT_EQ(l.column, 2);
  EXPECT_EQ(p.map.locate(7).line, 4);  // 'e'
  EXPECT_EQ(p.map.locate(7).column, 1);
  EXPECT_EQ(p.map.locate(8).column, 2);
}

TEST(preproc_source_map, ColumnsAfterAnExpansionAreTheOriginalOnes) {
  DiagnosticList d;
  //                       line 2: "x = LONG_NAME + y"
  const Preprocessed p = run("#define LONG_NAME 7\nx = LONG_NAME + y\n", d);
  ASSERT_EQ(p.text, "\nx = 7 + y\n");
  const size_t seven = p.text.find('7');
  const size_t y = p.text.find('y');
  const Location at7 = p.map.locate(seven);
  EXPECT_EQ(at7.line, 2);
  EXPECT_EQ(at7.column, 5);
  const Location aty = p.map.locate(y);
  EXPECT_EQ(aty.line, 2);
  EXPECT_EQ(aty.column, 17);  // "x = LONG_NAME + y": y is the 17th character

  ASSERT_EQ(p.map.expansions.size(), 1u);
  const Expansion& e = p.map.expansions[0];
  EXPECT_EQ(e.macro, "LONG_NAME");
  EXPECT_EQ(e.begin, seven);
  EXPECT_EQ(e.end, seven + 1);
  EXPECT_EQ(e.used_at.line, 2);
  EXPECT_EQ(e.used_at.column, 5);
  EXPECT_EQ(e.defined_at.line, 1);
  EXPECT_EQ(e.defined_at.column, 1);
  EXPECT_EQ(p.map.expansion_at(seven), &e);
  EXPECT_EQ(p.map.expansion_at(y), nullptr);
}

TEST(preproc_source_map, EveryCharacterOfAStringExpansionMapsToTheUse) {
  DiagnosticList d;
  const Preprocessed p = run("#define SPEED 10\n#define GO  JV=SPEED;BG\n  GO;GO\n", d);
  ASSERT_EQ(p.text, "\n\n  JV=10;BG;JV=10;BG\n");
  ASSERT_EQ(p.map.expansions.size(), 2u);
  for (size_t i = p.map.expansions[1].begin; i < p.map.expansions[1].end; ++i) {
    const Location l = p.map.locate(i);
    EXPECT_EQ(l.line, 3);
    EXPECT_EQ(l.column, 6);  // the second GO
  }
  EXPECT_EQ(p.map.expansions[1].defined_at.line, 2);
  const size_t semicolon = p.text.find(';', p.map.expansions[0].end);
  EXPECT_EQ(semicolon, p.map.expansions[0].end);
  EXPECT_EQ(p.map.locate(semicolon).column, 5);
}

TEST(preproc_source_map, LinesAfterDirectivesAndSkippedBlocksKeepTheirNumbers) {
  DiagnosticList d;
  const Preprocessed p = run("#if 0\nskipped\n#endif\n  keep\n", d);
  ASSERT_EQ(p.text, "\n\n\n  keep\n");
  const Location l = p.map.locate(p.text.find('k'));
  EXPECT_EQ(l.line, 4);
  EXPECT_EQ(l.column, 3);
}

TEST(preproc_source_map, CrlfLinesAndEndOfText) {
  DiagnosticList d;
  const Preprocessed p = run("#define A 1\r\nx=A\r\n", d);
  EXPECT_EQ(p.text, "\nx=1\r\n");
  EXPECT_EQ(p.map.locate(p.text.size()).line, 3);
  const Preprocessed empty = run("", d);
  EXPECT_EQ(empty.text, "");
  EXPECT_EQ(empty.map.locate(0).line, 1);
  EXPECT_EQ(empty.map.locate(100).line, 1);
}

TEST(preproc_source_map, DiagnosticsNamePlacesInTheSource) {
  DiagnosticList d;
  run("x\n  #define NUM 3\n  #define NUM 4\n", d);
  ASSERT_EQ(d.items().size(), 1u);
  const Diagnostic& e = d.items()[0];
  EXPECT_EQ(e.code, 89);
  EXPECT_EQ(e.where.file, "m.prg");
  EXPECT_EQ(e.where.line, 3);
  EXPECT_EQ(e.where.column, 11);
  ASSERT_EQ(e.notes.size(), 1u);
  EXPECT_EQ(e.notes[0].where.line, 2);  // the first definition
}

TEST(preproc_source_map, LocateOnAManyLineFileMatchesALinearScan) {
  std::string src;
  for (int i = 0; i < 2000; ++i)
    src += (i % 7 == 0 ? "#define M" + std::to_string(i) + " " + std::to_string(i) + "\n"
                       : "a M" + std::to_string(i - i % 7) + " b\n");
  DiagnosticList d;
  const Preprocessed p = run(src, d);
  // Walk the output: lines count by '\n'; outside expansions the column restarts after each one.
  int line = 1;
  for (size_t i = 0; i < p.text.size(); ++i) {
    const Location l = p.map.locate(i);
    ASSERT_EQ(l.line, line) << "offset " << i;
    if (p.text[i] == '\n') ++line;
  }
  EXPECT_EQ(line, 2001);
}

// Gold's codes are the default; a dialect maps the same errors to its own codes and texts.
TEST(preproc_source_map, DialectCodesAndTexts) {
  PreprocOptions o;
  o.scheme = "pdl";
  o.code_of = [](PreprocError e) { return e == PreprocError::NotDefined ? 1234 : 1; };
  o.text_of = [](PreprocError) { return "pdl text"; };
  DiagnosticList d;
  preprocess({"p.pdl", "#undef Q\n"}, o, d);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].scheme, "pdl");
  EXPECT_EQ(d.items()[0].code, 1234);
  EXPECT_EQ(d.items()[0].message, "pdl text");
}

// #include: the included lines stand in place of the directive and map to their own file,
// line and column (found beside the including file); the lines after map to the source again.
TEST(preproc_source_map, IncludedLinesMapToTheirFile) {
  PreprocOptions o;
  o.allow_include = true;
  o.read_file = [](const std::string& path, std::string* why) -> std::optional<std::string> {
    if (path == "dir/a.h") return std::string("#define K 5\nx = K\n#include \"b.h\"");
    if (path == "dir/b.h") return std::string("  yy");
    *why = "absent";
    return std::nullopt;
  };
  DiagnosticList d;
  const Preprocessed p = preprocess({"dir/m.prg", "one\n#include \"a.h\"\ntwo"}, o, d);
  ASSERT_TRUE(d.items().empty());
  ASSERT_EQ(p.text, "one\n\nx = 5\n  yy\ntwo");
  const Location x = p.map.locate(p.text.find('x'));
  EXPECT_EQ(x.file, "dir/a.h");
  EXPECT_EQ(x.line, 2);
  EXPECT_EQ(x.column, 1);
  const Location y = p.map.locate(p.text.find("yy"));
  EXPECT_EQ(y.file, "dir/b.h");
  EXPECT_EQ(y.line, 1);
  EXPECT_EQ(y.column, 3);
  const Location two = p.map.locate(p.text.find("two"));
  EXPECT_EQ(two.file, "dir/m.prg");
  EXPECT_EQ(two.line, 3);
  EXPECT_EQ(two.column, 1);
}

// A file that includes itself stops at max_include_depth, reported in that file.
TEST(preproc_source_map, IncludeDepthIsBounded) {
  PreprocOptions o;
  o.allow_include = true;
  o.max_include_depth = 3;
  int reads = 0;
  o.read_file = [&reads](const std::string&, std::string*) -> std::optional<std::string> {
    ++reads;
    return std::string("#include \"s.h\"");
  };
  DiagnosticList d;
  preprocess({"s.h", "#include \"s.h\""}, o, d);
  EXPECT_EQ(reads, 3);
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].where.file, "s.h");
  EXPECT_EQ(d.items()[0].where.column, 10);
}

}  // namespace
}  // namespace uprog::preproc
