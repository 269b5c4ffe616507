// End to end: `uprog sim` (the real controller) over TCP, the pty through socat, and `uprog term`,
// with many hosts, hostile ones among them, while a user program runs.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <thread>

#include "sim_process.h"
#include "test_client.h"

namespace uprog::transport {
namespace {

using namespace std::chrono_literals;
using testing::SimProcess;
using testing::TestClient;

const std::string kCounterProgram =
    std::string(UPROG_SOURCE_DIR) + "/tests/transport/data/counter.ehl";

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string run_shell(const std::string& command, int* status) {
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  *status = ::pclose(pipe);
  return output;
}

TEST(transport_sim, ManualCommandLinesOverTcpAndACleanStop) {
  SimProcess sim({"--listen", "127.0.0.1:0", "--safe-boot"});
  TestClient client(sim.port);
  ASSERT_TRUE(client.send("3+4\r"));
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"7", 0}}));
  ASSERT_TRUE(client.send("PX=7; PX-3\r\n"));
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"", 0}, {"4", 0}}));
  ASSERT_TRUE(client.send("(3.2+4)/2;"));
  EXPECT_EQ(client.answers(1, 5s), (std::vector<Reply>{{"3.600000", 0}}));
  ASSERT_TRUE(client.send("AC=-5\n"));
  const auto error = client.line_answers();
  ASSERT_EQ(error.size(), 1u);
  EXPECT_EQ(error[0].error, 21);
  EXPECT_EQ(sim.stop(), 0);  // SIGTERM: a clean exit
}

TEST(transport_sim, EightClientsTwoThousandLinesEachWhileAProgramRuns) {
  constexpr int kClients = 8;
  constexpr int kLines = 2000;
  SimProcess sim({"--listen", "127.0.0.1:0", "--program", kCounterProgram});
  TestClient watcher(sim.port);
  ASSERT_TRUE(watcher.send("UI[2]\n"));
  const auto count_before = std::stol(watcher.line_answers().at(0).text);

  const auto start = std::chrono::steady_clock::now();
  std::vector<int> correct(kClients, 0);
  std::vector<std::thread> threads;
  for (int c = 0; c < kClients; ++c) {
    threads.emplace_back([&, c] {
      TestClient client(sim.port);
      const std::string ui = "UI[" + std::to_string(3 + c) + "]";
      std::thread writer([&] {
        for (int i = 0; i < kLines; ++i) {
          if (!client.send(ui + "=" + std::to_string(i) + ";" + ui + "\n")) return;
        }
      });
      // Per line: the silent assignment's empty answer, then the value read back.
      const auto answers = client.answers(2 * kLines, 20s);
      writer.join();
      for (int i = 0; 2 * i + 1 < static_cast<int>(answers.size()); ++i) {
        if (answers[2 * i] != Reply{"", 0} || answers[2 * i + 1] != Reply{std::to_string(i), 0}) {
          break;
        }
        ++correct[c];
      }
    });
  }
  for (auto& t : threads) t.join();
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::steady_clock::now() - start);
  for (int c = 0; c < kClients; ++c) EXPECT_EQ(correct[c], kLines) << "client " << c;
  ASSERT_TRUE(watcher.send("UI[2];PS\n"));
  const auto after = watcher.line_answers();
  ASSERT_EQ(after.size(), 2u);
  EXPECT_GT(std::stol(after[0].text), count_before);  // the program kept running
  EXPECT_EQ(after[1].text, "1");                      // PS: running
  std::printf("uprog sim: 8 clients x 2000 lines (16000 lines, 32000 expressions): %lld ms\n",
              static_cast<long long>(ms.count()));
}

TEST(transport_sim, HostileHostsGetErrorsOrACleanCloseWhileOthersAreServed) {
  SimProcess sim({"--listen", "127.0.0.1:0", "--program", kCounterProgram});
  TestClient good(sim.port);
  auto ask = [&good](const std::string& line) {
    EXPECT_TRUE(good.send(line + "\n"));
    return good.line_answers();
  };
  EXPECT_EQ(ask("3+4"), (std::vector<Reply>{{"7", 0}}));

  // A 100 000-byte line: one error, then the host is served again.
  TestClient huge(sim.port);
  ASSERT_TRUE(huge.send(std::string(100'000, '1') + "\n3+4\n"));
  EXPECT_EQ(huge.line_answers(), (std::vector<Reply>{{"Line too long", kErrorLineTooLong}}));
  EXPECT_EQ(huge.line_answers(), (std::vector<Reply>{{"7", 0}}));
  EXPECT_EQ(ask("1+1"), (std::vector<Reply>{{"2", 0}}));

  // Binary garbage: only error answers, then a normal line is served.
  TestClient garbage(sim.port);
  std::mt19937 random(99);
  std::string bytes(50'000, '\0');
  for (char& ch : bytes) ch = static_cast<char>(random() & 0xff);
  std::thread writer([&] { garbage.send(bytes + "\n5+5\n"); });
  bool served = false;
  for (int i = 0; i < 50'000 && !served; ++i) {
    const auto answer = garbage.answers(1, 10s);
    if (answer.empty()) break;
    served = answer.front() == Reply{"10", 0};
  }
  writer.join();
  EXPECT_TRUE(served);
  EXPECT_EQ(ask("2+2"), (std::vector<Reply>{{"4", 0}}));

  // A host that leaves mid-line: its half line never runs.
  {
    TestClient leaving(sim.port);
    ASSERT_TRUE(leaving.send("UI[11]=5\nUI[11]=77"));
    EXPECT_EQ(leaving.line_answers(), (std::vector<Reply>{{"", 0}}));
  }
  std::this_thread::sleep_for(100ms);
  EXPECT_EQ(ask("UI[11]"), (std::vector<Reply>{{"5", 0}}));
  EXPECT_EQ(sim.stop(), 0);
}

TEST(transport_sim, PtyThroughSocat) {
  SimProcess sim({"--pty", "--safe-boot"});
  ASSERT_TRUE(sim.pty_path.starts_with("/dev/pts/"));
  int status = 0;
  const auto output = run_shell(
      "printf 'PX=7; PX-3\\r3+4\\r' | timeout 10 socat -t 1 - " + sim.pty_path + ",raw,echo=0 2>&1",
      &status);
  EXPECT_EQ(status, 0) << output;
  EXPECT_EQ(output, ";4;\r\n7;\r\n");
}

TEST(transport_sim, TermInPipeMode) {
  SimProcess sim({"--listen", "127.0.0.1:0", "--safe-boot"});
  const std::string term =
      std::string(UPROG_BINARY) + " term 127.0.0.1:" + std::to_string(sim.port);
  int status = 0;
  auto output =
      run_shell("printf 'PX=7; PX-3\\n\\n** a comment\\n(3.2+4)/2\\nAC=-5\\n' | " + term, &status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(output.substr(0, 11), "4\n3.600000\n");
  EXPECT_TRUE(output.substr(11).starts_with("?21")) << output;
  output = run_shell("printf 'AC=-5\\n' | " + term + " --fail-on-error", &status);
  EXPECT_EQ(WEXITSTATUS(status), 4);
  output = run_shell(std::string(UPROG_BINARY) + " term 127.0.0.1:1 </dev/null 2>&1", &status);
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(output.find("cannot connect"), std::string::npos);
}

// A PDL drive (examples/pdl/printl_report.pdl): after `reset`, task 2's five printl reports
// reach `uprog term` as the drive sends them (10 ms apart, `<<` marks a line the drive sent on
// its own), before the answer to the line typed a second later. The values are the program's:
// level = step*step in %04x, ratio = level/25.
TEST(transport_sim, TermShowsPdlPrintlEventsAsTheyArrive) {
  SimProcess sim({"--listen", "127.0.0.1:0", "--program",
                  std::string(UPROG_SOURCE_DIR) + "/examples/pdl/printl_report.pdl"});
  const std::string term =
      std::string(UPROG_BINARY) + " term 127.0.0.1:" + std::to_string(sim.port);
  int status = 0;
  const std::string output =
      run_shell("(printf 'reset\\n'; sleep 1; printf 'step\\n') | " + term + " 2>&1", &status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const char* const kReports[] = {"step=1 level=0001 ratio=0.04", "step=2 level=0004 ratio=0.16",
                                  "step=3 level=0009 ratio=0.36", "step=4 level=0010 ratio=0.64",
                                  "step=5 level=0019 ratio=1"};
  size_t at = 0;
  for (const char* r : kReports) {
    at = output.find(std::string("<< %P 2 00000103 00000000 ramp report : ") + r, at);
    ASSERT_NE(at, std::string::npos) << r << " missing or out of order in:\n" << output;
  }
  EXPECT_TRUE(output.ends_with("\n5\n")) << output;
}

// The drive form, as the SimplIQ software manual describes it (MAN-SIMSW 3.1, 3.2): every byte
// echoed while EO=1, before the answer to the expression it ends; a value `VALUE;`, an error its
// EC code as one byte and `?;`; an empty expression answered `;`; nothing between lines.
TEST(transport_sim, DriveFormByteForByte) {
  SimProcess sim({"--listen", "127.0.0.1:0", "--safe-boot", "--wire", "drive"});
  TestClient client(sim.port);
  ASSERT_TRUE(client.send("PX=7;PX-3\r3+4\rAC=-5\r\rEO=0\rPX;MO\rAC=-5\rEC\r"));
  const std::string expected =
      "PX=7;;PX-3\r4;"  // echo, answer, echo, answer
      "3+4\r7;"
      "AC=-5\r\x15?;"  // 21: out of the command's range
      "\r;"            // an empty line gets the empty answer
      "EO=0\r;"        // still echoed: the echo was on when its bytes came
      "7;0;"           // no echo from here on
      "\x15?;"
      "21;";  // EC names the last error
  EXPECT_EQ(client.raw(expected.size(), 5s), expected);
  EXPECT_EQ(client.raw(1, 300ms), "");  // no line end, no prompt
  // A line too long for the drive is a syntax error (19) there, and the drive goes on.
  ASSERT_TRUE(client.send(std::string(600, '1') + "\rPX\r"));
  EXPECT_EQ(client.raw(5, 5s), "\x13?;7;");
}

TEST(transport_sim, TermAndDownloadSpeakTheDriveForm) {
  SimProcess sim({"--listen", "127.0.0.1:0", "--safe-boot", "--wire", "drive"});
  const std::string address = "127.0.0.1:" + std::to_string(sim.port);
  int status = 0;
  // Echo on at first, then off: the answers are the same; the error gets the dialect's text.
  const auto output =
      run_shell("printf 'PX=7; PX-3\\nAC=-5\\n** a comment\\nEO=0\\nVR\\nPX;PX+1\\n' | " +
                    std::string(UPROG_BINARY) + " term " + address,
                &status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << output;
  EXPECT_EQ(output,
            "4\n?21 Value out of the command's range\nuprog simulated Gold drive 1.0\n7\n8\n");
  const auto download = run_shell(
      std::string(UPROG_BINARY) + " download " + address + " " + kCounterProgram + " --load 2>&1",
      &status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << download;
  EXPECT_NE(download.find("loaded into RAM (CC)"), std::string::npos) << download;
}

TEST(transport_sim, DownloadOverTheWireWithUprogDownload) {
  char pattern[] = "/tmp/uprog_sim_download_XXXXXX";
  ASSERT_NE(::mkdtemp(pattern), nullptr);
  const std::string dir = pattern;
  SimProcess sim({"--listen", "127.0.0.1:0", "--safe-boot", "--state", dir});
  const std::string address = "127.0.0.1:" + std::to_string(sim.port);
  const std::string download = std::string(UPROG_BINARY) + " download " + address + " ";
  int status = 0;
  auto output = run_shell(download + kCounterProgram + " --load 2>&1", &status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << output;
  EXPECT_NE(output.find("downloaded"), std::string::npos) << output;
  EXPECT_NE(output.find("loaded into RAM (CC)"), std::string::npos) << output;
  const auto stored = read_file(dir + "/program.upi");
  ASSERT_FALSE(stored.empty());
  TestClient client(sim.port);
  ASSERT_TRUE(client.send("PS\n"));
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"-1", 0}}));

  // A transfer belongs to its connection: a host that goes away mid-transfer takes it along.
  {
    TestClient leaving(sim.port);
    ASSERT_TRUE(leaving.send("DL##BEGIN=4\nDL=0102\n"));
    EXPECT_EQ(leaving.answers(2, 5s).size(), 2u);
    ASSERT_TRUE(client.send("DL=0304\n"));  // another host: it began nothing
    const auto chunk = client.line_answers();
    ASSERT_EQ(chunk.size(), 1u);
    EXPECT_EQ(chunk[0].error, 210);
  }
  {
    TestClient back(sim.port);  // the first host again, on a new connection: nothing to end
    ASSERT_TRUE(back.send("DL##END\n"));
    const auto end = back.line_answers();
    ASSERT_EQ(end.size(), 1u);
    EXPECT_EQ(end[0].error, 210);
  }
  // A corrupt image and a source with errors: exit status 1, the stored program unchanged.
  auto corrupt = stored;
  corrupt[corrupt.size() / 2] = static_cast<char>(corrupt[corrupt.size() / 2] ^ 0x10);
  const std::string corrupt_path = dir + "/corrupt.upi";
  { std::ofstream(corrupt_path, std::ios::binary) << corrupt; }
  output = run_shell(download + corrupt_path + " 2>&1", &status);
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(output.find("?213"), std::string::npos) << output;
  const std::string broken_path = dir + "/broken.ehl";
  { std::ofstream(broken_path) << "function main()\n  x = = 3\nreturn\n"; }
  output = run_shell(download + broken_path + " 2>&1", &status);
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(output.find("broken.ehl:2"), std::string::npos) << output;
  EXPECT_EQ(read_file(dir + "/program.upi"), stored);
  ASSERT_TRUE(client.send("PS\n"));
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"-1", 0}}));
  EXPECT_EQ(sim.stop(), 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace uprog::transport
