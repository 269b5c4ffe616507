// Which targets name a file of the page (page_files.h): only plain names under its folder.
#include "studio/page_files.h"

#include <gtest/gtest.h>

namespace uprog::studio {
namespace {

TEST(PageFiles, TheRootIsTheIndexAndAQueryIsIgnored) {
  EXPECT_EQ(page_file_path("/p", "/"), "/p/index.html");
  EXPECT_EQ(page_file_path("/p", "/app.js?v=2"), "/p/app.js");
  EXPECT_EQ(page_file_path("/p", "/assets/font.woff2"), "/p/assets/font.woff2");
}

TEST(PageFiles, NothingOutsideTheFolderNorHidden) {
  for (const char* target : {"/../etc/passwd", "/a/../../x", "/.git/config", "//etc/passwd",
                             "/a%2f..%2fb", "/a\\b", "relative", "", "/assets/", "/a//b"}) {
    EXPECT_EQ(page_file_path("/p", target), std::nullopt) << target;
  }
}

TEST(PageFiles, ContentTypes) {
  EXPECT_EQ(content_type("/p/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(content_type("/p/app.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type("/p/x.bin"), "application/octet-stream");
}

}  // namespace
}  // namespace uprog::studio
