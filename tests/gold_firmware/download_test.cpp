// Downloading over the command line (a dialect::Session of the Gold firmware): a good image in DL
// lines is stored, and every malformed transfer gets its error and leaves the stored program as it
// was.
#include <gtest/gtest.h>

#include <filesystem>

#include "bytecode/image.h"
#include "compile_bytes.h"
#include "dialect/dl_lines.h"
#include "dialects/gold/compile.h"
#include "dialects/gold/interpreter_errors.h"
#include "gold_drive.h"
#include "support/files.h"

namespace uprog::controller {
namespace {

// "" for success (no answer), "!CODE" for an error, else the value.
std::string one(dialect::Session& c, const std::string& line) {
  const std::vector<Answer> a = c.send(line);
  if (a.empty()) return "";
  if (a.size() != 1) return "<" + std::to_string(a.size()) + " answers>";
  return a[0].is_error() ? "!" + std::to_string(a[0].error) : a[0].text;
}

// Sends every line; the first answer that is not silent, or "".
std::string send_all(dialect::Session& c, const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    if (std::string a = one(c, line); !a.empty()) return a;
  }
  return "";
}

std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("uprog_download_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

const std::string kProgramA = "int a;\nfunction main()\n  a = 11;\nreturn\n";
const std::string kProgramB = "int b;\nfunction main()\n  b = 22;\nreturn\n";

TEST(controller_download, LinesStayWithinTheLineLimit) {
  const std::vector<uint8_t> image(1000, 0xAB);
  const auto lines = dialect::download_lines(image);
  ASSERT_EQ(lines.size(),
            2u + (1000 + dialect::kDownloadChunkBytes - 1) / dialect::kDownloadChunkBytes);
  EXPECT_EQ(lines.front(), "DL##BEGIN=1000");
  EXPECT_EQ(lines.back(), "DL##END");
  for (const auto& l : lines) EXPECT_LE(l.size(), 511u);
}

TEST(controller_download, AnImageSentInLinesIsStoredAndRuns) {
  const std::string dir = temp_dir("good");
  ControllerOptions o = gold_options();
  o.state_dir = dir;
  Controller drive(o);
  auto host_session = drive.open_session();
  dialect::Session& host = *host_session;
  const auto image = compile_bytes(kProgramA);
  EXPECT_EQ(send_all(host, dialect::download_lines(image)), "");
  EXPECT_EQ(read_binary_file(dir + "/program.upi"), image);
  EXPECT_EQ(one(host, "CC"), "");
  EXPECT_EQ(one(host, "XQ##main"), "");
  drive.advance(10'000);
  EXPECT_EQ(one(host, "a"), "11");
  // Lower case, blanks and a whole transfer in one host line (`;`-separated) work alike.
  const auto b = compile_bytes(kProgramB);
  auto lines = dialect::download_lines(b);
  lines[0] = "dl ## begin = " + std::to_string(b.size());
  std::string joined;
  for (const auto& l : lines) joined += l + ";";
  EXPECT_EQ(one(host, joined), "");
  EXPECT_EQ(read_binary_file(dir + "/program.upi"), b);
  std::filesystem::remove_all(dir);
}

TEST(controller_download, BadTransfersAreRefusedAndThePreviousProgramStays) {
  const std::string dir = temp_dir("bad");
  ControllerOptions o = gold_options();
  o.state_dir = dir;
  Controller drive(o);
  auto host_session = drive.open_session();
  dialect::Session& host = *host_session;
  const auto a = compile_bytes(kProgramA);
  ASSERT_EQ(send_all(host, dialect::download_lines(a)), "");

  const auto b = compile_bytes(kProgramB);
  const auto good = dialect::download_lines(b);
  EXPECT_EQ(one(host, "DL##END"), "!210");  // nothing is in progress any more
  EXPECT_EQ(one(host, "DL=0102"), "!210");
  EXPECT_EQ(one(host, "DL##BEGIN=0"), "!211");
  EXPECT_EQ(one(host, "DL##BEGIN=1048577"), "!211");  // over the 1 MiB cap
  EXPECT_EQ(one(host, "DL##BEGIN=99999999999999999999999"), "!211");
  EXPECT_EQ(one(host, "DL##BEGIN=-5"), "!211");
  EXPECT_EQ(one(host, "DL##BEGIN=12x"), "!211");
  EXPECT_EQ(one(host, "DL##BEGIN"), "!19");
  EXPECT_EQ(one(host, "DL##WHATEVER"), "!19");
  // A garbage chunk drops the transfer: the rest of it is refused too.
  EXPECT_EQ(one(host, good[0]), "");
  EXPECT_EQ(one(host, "DL=0G"), "!212");
  EXPECT_EQ(one(host, good[1]), "!210");
  EXPECT_EQ(one(host, "DL##END"), "!210");  // nothing is in progress any more
  // An odd number of digits, an empty chunk.
  EXPECT_EQ(one(host, good[0]), "");
  EXPECT_EQ(one(host, "DL=ABC"), "!212");
  EXPECT_EQ(one(host, good[0]), "");
  EXPECT_EQ(one(host, "DL="), "!212");
  // More bytes than announced.
  EXPECT_EQ(one(host, "DL##BEGIN=1"), "");
  EXPECT_EQ(one(host, "DL=0102"), "!212");
  // Too few bytes at END.
  EXPECT_EQ(one(host, good[0]), "");
  EXPECT_EQ(one(host, good[1].substr(0, 9)), "");
  EXPECT_EQ(one(host, "DL##END"), "!211");
  // ABORT drops a transfer, and BEGIN starts afresh.
  EXPECT_EQ(one(host, good[0]), "");
  EXPECT_EQ(one(host, good[1]), "");
  EXPECT_EQ(one(host, "DL##ABORT"), "");
  EXPECT_EQ(one(host, "DL##END"), "!210");  // nothing is in progress any more
  // The right size but corrupt bytes: the CRC refuses it.
  auto corrupt = b;
  corrupt[corrupt.size() / 2] ^= 0x40;
  EXPECT_EQ(send_all(host, dialect::download_lines(corrupt)), "!213");
  // Not an image at all.
  EXPECT_EQ(send_all(host, dialect::download_lines(std::vector<uint8_t>(300, 7))), "!213");
  // Other lines between DL lines are served as usual; the transfer goes on.
  EXPECT_EQ(one(host, good[0]), "");
  EXPECT_EQ(one(host, "3+4"), "7");
  EXPECT_EQ(one(host, "PS"), "-2");

  EXPECT_EQ(read_binary_file(dir + "/program.upi"), a);  // through all of that, A stays
  std::filesystem::remove_all(dir);
}

TEST(controller_download, EachHostHasItsOwnTransfer) {
  Controller drive(gold_options());
  auto first_session = drive.open_session(), second_session = drive.open_session();
  dialect::Session &first = *first_session, &second = *second_session;
  const auto image = compile_bytes(kProgramA);
  const auto lines = dialect::download_lines(image);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(one(first, lines[0]), "");
  EXPECT_EQ(one(second, lines[1]), "!210");  // the second host has begun nothing
  EXPECT_EQ(one(second, "DL##END"), "!210");
  for (size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(one(first, lines[i]), "") << lines[i];
  EXPECT_EQ(one(second, "CC"), "");  // stored for the whole drive
  EXPECT_EQ(one(second, "LS"), "<2 answers>");
}

TEST(controller_download, AnUnwritableStateDirIsAStorageError) {
  const std::string dir = temp_dir("unwritable");
  ControllerOptions o = gold_options();
  o.state_dir = dir;
  Controller drive(o);
  auto host_session = drive.open_session();
  dialect::Session& host = *host_session;
  // A directory where the program file would go makes the atomic replacement fail.
  std::filesystem::create_directories(dir + "/program.upi/x");
  EXPECT_EQ(send_all(host, dialect::download_lines(compile_bytes(kProgramA))), "!206");
  EXPECT_TRUE(std::filesystem::is_directory(dir + "/program.upi"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace uprog::controller
