// The transfer every dialect's download shares (dialect/download_receiver.h), with the codes of
// the DL lines (docs/protocol.md, "Download": 210 no transfer, 211 a bad size or too few bytes,
// 212 bad hex or too many bytes) and the AG300's fixed texts (shared/spec/akribis-drive.md).
#include "dialect/download_receiver.h"

#include <gtest/gtest.h>

#include "dialect/dl_lines.h"

namespace uprog::dialect {
namespace {

constexpr DownloadCodes kCodes{
    .not_begun = {210}, .bad_size = {211}, .bad_data = {212}, .too_many = {212}, .too_few = {211}};

int32_t code_of(const std::optional<Answer>& a) { return a ? a->error : 0; }

TEST(DownloadReceiver, GathersTheAnnouncedBytes) {
  DownloadReceiver r(8, kCodes);
  EXPECT_EQ(code_of(r.begin("3")), 0);
  EXPECT_EQ(code_of(r.add_hex("0aFF")), 0);
  EXPECT_EQ(code_of(r.add_hex("10")), 0);
  std::vector<uint8_t> done;
  EXPECT_EQ(code_of(r.finish(done)), 0);
  EXPECT_EQ(done, (std::vector<uint8_t>{0x0A, 0xFF, 0x10}));
  EXPECT_FALSE(r.in_progress());
}

TEST(DownloadReceiver, SizesOutsideOneToTheLimitAreRefused) {
  DownloadReceiver r(8, kCodes);
  EXPECT_EQ(code_of(r.begin("0")), 211);
  EXPECT_EQ(code_of(r.begin("9")), 211);
  EXPECT_EQ(code_of(r.begin("")), 211);
  EXPECT_EQ(code_of(r.begin("3x")), 211);
  EXPECT_EQ(code_of(r.begin("-1")), 211);
  EXPECT_EQ(code_of(r.begin("8")), 0);
}

TEST(DownloadReceiver, EveryFaultDropsTheTransfer) {
  DownloadReceiver r(8, kCodes);
  ASSERT_EQ(code_of(r.begin("2")), 0);
  EXPECT_EQ(code_of(r.add_hex("0")), 212);  // an odd number of digits
  EXPECT_EQ(code_of(r.add_hex("00")), 210);
  ASSERT_EQ(code_of(r.begin("2")), 0);
  EXPECT_EQ(code_of(r.add_hex("0G")), 212);
  ASSERT_EQ(code_of(r.begin("2")), 0);
  EXPECT_EQ(code_of(r.add_hex("")), 212);
  ASSERT_EQ(code_of(r.begin("2")), 0);
  EXPECT_EQ(code_of(r.add_hex("000000")), 212);  // more than announced
  ASSERT_EQ(code_of(r.begin("2")), 0);
  ASSERT_EQ(code_of(r.add_hex("00")), 0);
  std::vector<uint8_t> done;
  ASSERT_EQ(code_of(r.begin("3")), 0);  // a new BEGIN starts afresh
  ASSERT_EQ(code_of(r.add_hex("01")), 0);
  EXPECT_EQ(code_of(r.finish(done)), 211);  // too few
  EXPECT_TRUE(done.empty());
  EXPECT_EQ(code_of(r.finish(done)), 210);
}

TEST(DownloadReceiver, ALineBringsAtMostItsLimit) {
  DownloadReceiver r(8, kCodes, 2);
  ASSERT_EQ(code_of(r.begin(size_t{4})), 0);
  EXPECT_EQ(code_of(r.add_hex("0102")), 0);
  EXPECT_EQ(code_of(r.add_hex("030405")), 212);
}

TEST(DownloadReceiver, ADialectsTableTextsReplaceTheDescription) {
  DownloadReceiver r(8, {.not_begun = {40, "download not begun"},
                         .bad_size = {41, "length"},
                         .bad_data = {42, "data"},
                         .too_many = {41, "length"},
                         .too_few = {41, "length"}});
  EXPECT_EQ(r.add_hex("00"), (Answer{"download not begun", 40}));
  ASSERT_FALSE(r.begin("1"));
  EXPECT_EQ(r.add_hex("0000"), (Answer{"length", 41}));
}

TEST(DlReceiver, TheFourLinesAndAnythingElse) {
  DlReceiver r;
  std::vector<uint8_t> done;
  EXPECT_TRUE(DlReceiver::is_download_command("dl ## begin = 2"));
  EXPECT_FALSE(DlReceiver::is_download_command("DLX"));
  EXPECT_FALSE(r.handle("dl##begin=2", done));
  EXPECT_FALSE(r.handle("DL = 7f 80", done));
  EXPECT_FALSE(r.handle("DL##END", done));
  EXPECT_EQ(done, (std::vector<uint8_t>{0x7F, 0x80}));
  EXPECT_EQ(code_of(r.handle("DL##BEGIN=1048577", done)), kDlBadSize);
  EXPECT_EQ(code_of(r.handle("DL##WHAT", done)), kDlSyntax);
}

TEST(DlReceiver, TheHostsLinesRoundTrip) {
  std::vector<uint8_t> image(600);
  for (size_t i = 0; i < image.size(); ++i) image[i] = static_cast<uint8_t>(i * 7);
  const std::vector<std::string> lines = download_lines(image);
  ASSERT_EQ(lines.size(), 2 + (600 + kDownloadChunkBytes - 1) / kDownloadChunkBytes);
  DlReceiver r;
  std::vector<uint8_t> done;
  for (const std::string& line : lines) ASSERT_FALSE(r.handle(line, done)) << line;
  EXPECT_EQ(done, image);
}

}  // namespace
}  // namespace uprog::dialect
