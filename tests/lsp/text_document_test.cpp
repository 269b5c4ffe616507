// Positions and edits as LSP 3.17 defines them ("Position": a character counts UTF-16 code units
// unless UTF-8 was agreed; a character past the line's end is the line's end), and file URIs.
#include "lsp/text_document.h"

#include <gtest/gtest.h>

#include "lsp/uri.h"

namespace uprog::lsp {
namespace {

// "é" is two UTF-8 bytes and one UTF-16 unit; "𝄞" (U+1D11E) four bytes and two units.
const std::string kText =
    "a\xC3\xA9"
    "b\n\xF0\x9D\x84\x9E"
    "c\r\nlast";

TEST(Positions, Utf16AndUtf8Characters) {
  EXPECT_EQ(offset_of(kText, {0, 2}, PositionEncoding::Utf16), 3u);  // after "aé"
  EXPECT_EQ(offset_of(kText, {0, 3}, PositionEncoding::Utf8), 3u);
  EXPECT_EQ(offset_of(kText, {1, 2}, PositionEncoding::Utf16), 9u);  // after the clef
  EXPECT_EQ(offset_of(kText, {1, 4}, PositionEncoding::Utf8), 9u);
  EXPECT_EQ(position_of(kText, 10, PositionEncoding::Utf16).character, 3);
  EXPECT_EQ(position_of(kText, 10, PositionEncoding::Utf8).character, 5);
  EXPECT_EQ(position_of(kText, 12, PositionEncoding::Utf16).line, 2);
}

TEST(Positions, PastTheEndIsClamped) {
  EXPECT_EQ(offset_of(kText, {0, 99}, PositionEncoding::Utf16), 4u);   // before "\n"
  EXPECT_EQ(offset_of(kText, {1, 99}, PositionEncoding::Utf16), 10u);  // before "\r\n"
  EXPECT_EQ(offset_of(kText, {9, 0}, PositionEncoding::Utf16), kText.size());
  EXPECT_EQ(offset_of(kText, {-1, -1}, PositionEncoding::Utf16), 0u);
}

TEST(TextDocument, IncrementalEdits) {
  TextDocument d;
  d.text = "x = 1\ny = 2\n";
  d.replace({1, 4}, {1, 5}, "42", PositionEncoding::Utf16);
  EXPECT_EQ(d.text, "x = 1\ny = 42\n");
  d.replace({0, 0}, {1, 0}, "", PositionEncoding::Utf16);
  EXPECT_EQ(d.text, "y = 42\n");
  d.replace({0, 5}, {0, 1}, "!", PositionEncoding::Utf16);  // an end before the start: inserted
  EXPECT_EQ(d.text, "y = 4!2\n");
}

TEST(Uri, FileUrisAndPaths) {
  EXPECT_EQ(path_from_uri("file:///home/a%20b/x.ehl"),
            std::optional<std::string>("/home/a b/x.ehl"));
  EXPECT_EQ(path_from_uri("file://localhost/x.pdl"), std::optional<std::string>("/x.pdl"));
  EXPECT_EQ(path_from_uri("untitled:Untitled-1"), std::nullopt);
  EXPECT_EQ(path_from_uri("file://server/share/x"), std::nullopt);
  EXPECT_EQ(path_from_uri("file:///x%2"), std::nullopt);
  EXPECT_EQ(path_from_uri("file:///x%00y"), std::nullopt);
  EXPECT_EQ(uri_from_path("/home/a b/x#1.ehl"), "file:///home/a%20b/x%231.ehl");
}

}  // namespace
}  // namespace uprog::lsp
