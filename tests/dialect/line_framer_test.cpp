// The line framer: terminators, comments, limits, garbage, chunking.
#include "dialect/line_framer.h"

#include <gtest/gtest.h>

#include <random>

namespace uprog::dialect {
namespace {

using Kind = Frame::Kind;

// The semicolon wire's framing (Gold, PDL, Akribis): `;` ends a line, `**` comments, 511.
FramerOptions semicolon_options() {
  FramerOptions o;
  o.max_line_length = 511;
  o.semicolon_ends_line = true;
  o.comment_marker = "**";
  return o;
}

std::vector<Frame> frame(std::string_view bytes, FramerOptions options = semicolon_options()) {
  LineFramer framer(options);
  std::vector<Frame> out;
  framer.feed(bytes, out);
  return out;
}

Frame line(std::string text) { return {Kind::kLine, std::move(text)}; }
const Frame kBreak{Kind::kLineBreak, {}};
const Frame kTooLong{Kind::kTooLong, {}};
const Frame kBad{Kind::kBadCharacter, {}};

TEST(transport_framer, EachTerminatorEndsALine) {
  EXPECT_EQ(frame("PX\r"), (std::vector<Frame>{line("PX"), kBreak}));
  EXPECT_EQ(frame("PX\n"), (std::vector<Frame>{line("PX"), kBreak}));
  EXPECT_EQ(frame("PX;"), (std::vector<Frame>{line("PX")}));
}

TEST(transport_framer, ManualExampleSplitsIntoTwoExpressions) {
  EXPECT_EQ(frame("PX=7; PX-3\r\n"), (std::vector<Frame>{line("PX=7"), line("PX-3"), kBreak}));
}

TEST(transport_framer, SemicolonBeforeLineEndIsIgnoredAndCrLfIsOneBreak) {
  EXPECT_EQ(frame("PX;\r\n"), (std::vector<Frame>{line("PX"), kBreak}));
  EXPECT_EQ(frame(";;\r\n\r\n\n"), (std::vector<Frame>{kBreak}));
}

TEST(transport_framer, BlankLinesGiveNothing) { EXPECT_TRUE(frame("\r\n  \t \n\r").empty()); }

TEST(transport_framer, IndentationIsTrimmed) {
  EXPECT_EQ(frame("   UI[1] = 3  \t\n"), (std::vector<Frame>{line("UI[1] = 3"), kBreak}));
}

TEST(transport_framer, CommentRunsToLineEndAndHidesSemicolons) {
  EXPECT_EQ(frame("PX=1 ** set; PX\nVX\n"),
            (std::vector<Frame>{line("PX=1"), kBreak, line("VX"), kBreak}));
  EXPECT_EQ(frame("** only a comment\n"), (std::vector<Frame>{kBreak}));
  EXPECT_EQ(frame("3*4*5\n"), (std::vector<Frame>{line("3*4*5"), kBreak}));
}

TEST(transport_framer, CommentMarkerMaySpanChunks) {
  LineFramer framer(semicolon_options());
  std::vector<Frame> out;
  framer.feed("PX=1 *", out);
  framer.feed("* c;omment\n", out);
  EXPECT_EQ(out, (std::vector<Frame>{line("PX=1"), kBreak}));
}

TEST(transport_framer, NoCommentMarkerWhenDisabled) {
  FramerOptions options = semicolon_options();
  options.comment_marker = "";
  EXPECT_EQ(frame("a**b\n", options), (std::vector<Frame>{line("a**b"), kBreak}));
}

TEST(transport_framer, SemicolonCanBeOrdinary) {
  FramerOptions options = semicolon_options();
  options.semicolon_ends_line = false;
  EXPECT_EQ(frame("a;b\n", options), (std::vector<Frame>{line("a;b"), kBreak}));
}

TEST(transport_framer, LineOfExactlyTheLimitPassesOneMoreIsTooLong) {
  const std::string at_limit(511, 'x');
  EXPECT_EQ(frame(at_limit + ";"), (std::vector<Frame>{line(at_limit)}));
  EXPECT_EQ(frame(at_limit + "y;"), (std::vector<Frame>{kTooLong}));
}

TEST(transport_framer, HugeLineGivesOneErrorThenResynchronises) {
  LineFramer framer(semicolon_options());
  std::vector<Frame> out;
  const std::string chunk(1000, 'A');
  for (int i = 0; i < 100; ++i) framer.feed(chunk, out);
  EXPECT_TRUE(out.empty());
  EXPECT_LE(framer.pending_size(), 511u);  // memory stays bounded
  framer.feed("\nPX\n", out);
  EXPECT_EQ(out, (std::vector<Frame>{kTooLong, kBreak, line("PX"), kBreak}));
}

TEST(transport_framer, NulAndBinaryBytesMakeTheLineBad) {
  EXPECT_EQ(frame(std::string("P\0X\n", 4)), (std::vector<Frame>{kBad, kBreak}));
  EXPECT_EQ(frame("\x1b[A;PX;"), (std::vector<Frame>{kBad, line("PX")}));
  EXPECT_EQ(frame("\xc3\xa9;"), (std::vector<Frame>{kBad}));
}

TEST(transport_framer, BinaryInsideACommentIsIgnored) {
  EXPECT_EQ(frame(std::string("PX ** \0\xff;\n", 11)), (std::vector<Frame>{line("PX"), kBreak}));
}

TEST(transport_framer, BackspaceAndDeleteEraseACharacter) {
  EXPECT_EQ(frame("PY\bX\r"), (std::vector<Frame>{line("PX"), kBreak}));
  EXPECT_EQ(frame("\x7fPXX\x7f;"), (std::vector<Frame>{line("PX")}));
}

TEST(transport_framer, ResetDropsAPartialLine) {
  LineFramer framer(semicolon_options());
  std::vector<Frame> out;
  framer.feed("PX=12", out);
  framer.reset();
  framer.feed("VX\n", out);
  EXPECT_EQ(out, (std::vector<Frame>{line("VX"), kBreak}));
}

TEST(transport_framer, ChunkingDoesNotChangeTheResult) {
  const std::string input =
      "PX=7; PX-3\r\n** c;c\n" + std::string(600, 'z') + ";UI[1]\x01;\tVX \n;;\r" + "AB\x7f" + "C;";
  const auto whole = frame(input);
  std::mt19937 random(42);
  for (int round = 0; round < 200; ++round) {
    LineFramer framer(semicolon_options());
    std::vector<Frame> out;
    std::size_t at = 0;
    while (at < input.size()) {
      const std::size_t n = std::min<std::size_t>(input.size() - at, 1 + random() % 7);
      framer.feed(std::string_view(input).substr(at, n), out);
      at += n;
    }
    ASSERT_EQ(out, whole) << "round " << round;
  }
  EXPECT_EQ(whole.size(), 10u);
}

TEST(transport_framer, RandomBytesNeverCrashAndStayBounded) {
  std::mt19937 random(7);
  LineFramer framer(semicolon_options());
  std::vector<Frame> out;
  std::string bytes(4096, '\0');
  for (int round = 0; round < 500; ++round) {
    for (char& c : bytes) c = static_cast<char>(random() & 0xff);
    out.clear();
    framer.feed(bytes, out);
    ASSERT_LE(framer.pending_size(), 511u);
    for (const Frame& f : out) {
      if (f.kind == Kind::kLine) {
        ASSERT_FALSE(f.text.empty());
        ASSERT_LE(f.text.size(), 511u);
        for (const char c : f.text) ASSERT_TRUE((c >= 0x20 && c < 0x7f) || c == '\t');
      }
    }
  }
}

// A real Elmo drive answers every terminator (MAN-SIMSW 3.1: CR or `;` ends a command), an empty
// expression too; CR LF is one terminator, a comment line no expression.
FramerOptions drive_options() {
  FramerOptions o = semicolon_options();
  o.answer_empty_expressions = true;
  return o;
}

TEST(transport_framer, DriveFormAnswersEmptyExpressions) {
  EXPECT_EQ(frame(";", drive_options()), (std::vector<Frame>{line("")}));
  EXPECT_EQ(frame("\r", drive_options()), (std::vector<Frame>{line("")}));
  EXPECT_EQ(frame("PX;\r", drive_options()), (std::vector<Frame>{line("PX"), line(""), kBreak}));
  EXPECT_EQ(frame("PX\r\nMO\r\n", drive_options()),
            (std::vector<Frame>{line("PX"), kBreak, line("MO"), kBreak}));
  EXPECT_EQ(frame("\n\n", drive_options()), (std::vector<Frame>{line(""), line("")}));
  EXPECT_EQ(frame("  ;", drive_options()), (std::vector<Frame>{line("")}));
  EXPECT_EQ(frame("** a comment\r", drive_options()), (std::vector<Frame>{kBreak}));
  // Without the option the same bytes give no empty lines.
  EXPECT_EQ(frame("PX;\r"), (std::vector<Frame>{line("PX"), kBreak}));
}

// A drive that prompts after every physical line (the S300): an empty line still ends with a
// break, CR, LF or CR LF alike (the LF of a CR LF ends nothing), and gives no line to answer.
TEST(transport_framer, BreakEmptyLinesEndsEveryPhysicalLine) {
  FramerOptions o;
  o.break_empty_lines = true;
  EXPECT_EQ(frame("\r", o), (std::vector<Frame>{kBreak}));
  EXPECT_EQ(frame("\r\n", o), (std::vector<Frame>{kBreak}));
  EXPECT_EQ(frame("\n\n", o), (std::vector<Frame>{kBreak, kBreak}));
  EXPECT_EQ(frame("  \r", o), (std::vector<Frame>{kBreak}));
  EXPECT_EQ(frame("PFB\r\n\r", o), (std::vector<Frame>{line("PFB"), kBreak, kBreak}));
  // Without the option an empty line gives nothing.
  EXPECT_EQ(frame("\r\n\r", FramerOptions{}), (std::vector<Frame>{}));
}

}  // namespace
}  // namespace uprog::dialect
