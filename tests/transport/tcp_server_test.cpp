// The TCP server with a fake drive: many hosts at once, order, hostile input, disconnects, pacing.
#include <gtest/gtest.h>

#include <random>

#include "server_fixture.h"
#include "test_client.h"

namespace uprog::transport {
namespace {

using namespace std::chrono_literals;
using testing::ServerFixture;
using testing::TestClient;

TEST(transport_tcp, AnswersALineAndEndsIt) {
  ServerFixture server;
  TestClient client(server.port());
  ASSERT_TRUE(client.send("PX=7; PX-3\r\n"));
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"PX=7", 0}, {"PX-3", 0}}));
  ASSERT_TRUE(client.send("err 21\n"));
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"Failed", 21}}));
}

TEST(transport_tcp, WhatTheDriveSendsOnItsOwnReachesEveryHostAsALineOfItsOwn) {
  ServerFixture server;
  TestClient first(server.port()), second(server.port());
  ASSERT_TRUE(first.send("a\r\n"));  // both connected before the drive speaks
  ASSERT_EQ(first.line_answers(), (std::vector<Reply>{{"a", 0}}));
  ASSERT_TRUE(second.send("b\r\n"));
  ASSERT_EQ(second.line_answers(), (std::vector<Reply>{{"b", 0}}));
  server.emit("%P 1 00000000 00000000 hello; world");
  EXPECT_EQ(first.output_lines(1, 5s),
            (std::vector<std::string>{"%P 1 00000000 00000000 hello  world"}));
  EXPECT_EQ(second.output_lines(1, 5s),
            (std::vector<std::string>{"%P 1 00000000 00000000 hello  world"}));
  // An answer after it is still an answer to its own line.
  ASSERT_TRUE(first.send("c\r\n"));
  EXPECT_EQ(first.line_answers(), (std::vector<Reply>{{"c", 0}}));
}

TEST(transport_tcp, EightClientsTwoThousandLinesEachAllAnsweredInOrder) {
  constexpr int kClients = 8;
  constexpr int kLines = 2000;
  ServerFixture server;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  std::vector<int> correct(kClients, 0);
  for (int c = 0; c < kClients; ++c) {
    threads.emplace_back([&, c] {
      TestClient client(server.port());
      std::thread writer([&] {
        for (int i = 0; i < kLines; ++i) {
          // Mixed terminators and chunking: one line per send, as a chatty host does.
          const char* end = i % 3 == 0 ? "\r\n" : i % 3 == 1 ? ";" : "\n";
          if (!client.send("c" + std::to_string(c) + "-" + std::to_string(i) + end)) return;
        }
      });
      const auto answers = client.answers(kLines, 15s);
      writer.join();
      for (int i = 0; i < static_cast<int>(answers.size()); ++i) {
        if (answers[i] != Reply{"c" + std::to_string(c) + "-" + std::to_string(i), 0}) break;
        ++correct[c];
      }
    });
  }
  for (auto& t : threads) t.join();
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::steady_clock::now() - start);
  for (int c = 0; c < kClients; ++c) EXPECT_EQ(correct[c], kLines) << "client " << c;
  EXPECT_EQ(server.lines_handled(), std::uint64_t{kClients} * kLines);
  std::printf("8 clients x 2000 lines: %lld ms\n", static_cast<long long>(ms.count()));
}

TEST(transport_tcp, HundredThousandByteLineGetsOneErrorThenServiceResumes) {
  ServerFixture server;
  TestClient hostile(server.port());
  TestClient other(server.port());
  ASSERT_TRUE(hostile.send(std::string(100'000, 'A')));
  ASSERT_TRUE(other.send("still here\n"));
  EXPECT_EQ(other.line_answers(), (std::vector<Reply>{{"still here", 0}}));
  ASSERT_TRUE(hostile.send("\nPX\n"));
  EXPECT_EQ(hostile.line_answers(), (std::vector<Reply>{{"Line too long", kErrorLineTooLong}}));
  EXPECT_EQ(hostile.line_answers(), (std::vector<Reply>{{"PX", 0}}));
  EXPECT_EQ(server.lines_handled(), 2u);
}

TEST(transport_tcp, BinaryGarbageGetsErrorsNeverACrash) {
  ServerFixture server;
  TestClient hostile(server.port());
  std::mt19937 random(1234);
  std::string garbage(200'000, '\0');
  for (char& c : garbage) c = static_cast<char>(random() & 0xff);
  std::thread writer([&] { hostile.send(garbage + "\nping\n"); });
  // Every answer to garbage is an error; the last line is served normally.
  std::vector<Reply> got;
  for (int i = 0; i < 100'000; ++i) {
    auto answers = hostile.answers(1, 10s);
    if (answers.empty()) break;
    got.push_back(answers.front());
    if (answers.front() == Reply{"ping", 0}) break;
  }
  writer.join();
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.back(), (Reply{"ping", 0}));
  std::size_t errors = 0;
  for (const auto& reply : got)
    errors += reply.error == kErrorBadCharacter || reply.error == kErrorLineTooLong;
  EXPECT_GT(errors, 100u);
  TestClient other(server.port());
  ASSERT_TRUE(other.send("fine\n"));
  EXPECT_EQ(other.line_answers(), (std::vector<Reply>{{"fine", 0}}));
}

TEST(transport_tcp, ClientDisconnectingMidLineIsCleanedUp) {
  ServerFixture server;
  {
    TestClient leaving(server.port());
    ASSERT_TRUE(leaving.send("done;PX=12"));
    EXPECT_EQ(leaving.answers(1, 5s), (std::vector<Reply>{{"done", 0}}));
  }
  TestClient other(server.port());
  ASSERT_TRUE(other.send("next\n"));
  EXPECT_EQ(other.line_answers(), (std::vector<Reply>{{"next", 0}}));
  EXPECT_EQ(server.lines_handled(), 2u);  // the half line was never run
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  while (server.session_count() != 1 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_EQ(server.session_count(), 1u);
}

TEST(transport_tcp, HalfClosedClientStillGetsItsAnswersThenTheConnectionCloses) {
  ServerFixture server;
  TestClient client(server.port());
  ASSERT_TRUE(client.send("a;b;c\n"));
  client.shutdown_write();
  EXPECT_EQ(client.line_answers(), (std::vector<Reply>{{"a", 0}, {"b", 0}, {"c", 0}}));
  EXPECT_TRUE(client.closed_by_peer(5s));
}

TEST(transport_tcp, ClientThatNeverReadsDoesNotStallOthers) {
  ServerFixture server;
  TestClient flooder(server.port());
  // 10 MB of lines whose answers are 10 MB: more than the kernel's socket buffers hold.
  constexpr std::size_t kFloodLines = 5'000'000;
  std::string flood;
  flood.reserve(2 * kFloodLines);
  for (std::size_t i = 0; i < kFloodLines; ++i) flood += "x;";
  std::thread writer([&] { flooder.send(flood); });  // blocks once the server stops reading
  std::this_thread::sleep_for(300ms);
  TestClient other(server.port());
  ASSERT_TRUE(other.send("alive\n"));
  EXPECT_EQ(other.line_answers(2s), (std::vector<Reply>{{"alive", 0}}));
  const auto handled = server.lines_handled();
  EXPECT_LT(handled, kFloodLines);      // back-pressure: the flood is not all taken in
  ::shutdown(flooder.fd(), SHUT_RDWR);  // unblocks the writer with an error
  writer.join();
}

// Past 256 KiB queued for a host, the drive's texts are dropped; once there is room again, a
// wire that counts them says how many (PDL's `%L n`), before the texts that follow.
TEST(transport_tcp, AHostThatFallsBehindIsToldHowManyTextsItLost) {
  ServerFixture server;
  server.count_lost_output();
  TestClient client(server.port());
  ASSERT_TRUE(client.send("a\r\n"));
  ASSERT_EQ(client.line_answers(), (std::vector<Reply>{{"a", 0}}));
  constexpr int kTexts = 100'000;  // ~1.2 MB, in one turn: most cannot be queued
  server.emit_numbered(0, kTexts);
  int kept = 0;
  std::string notice;
  while (notice.empty()) {
    const std::vector<std::string> line = client.output_lines(1, 5s);
    ASSERT_EQ(line.size(), 1u) << "after " << kept << " texts";
    if (line[0].starts_with("%L ")) {
      notice = line[0];
    } else {
      ASSERT_EQ(line[0], "text " + std::to_string(kept));  // in order, none lost before the notice
      ++kept;
    }
  }
  EXPECT_GT(kept, 0);
  EXPECT_LT(kept, kTexts);
  EXPECT_EQ(notice, "%L " + std::to_string(kTexts - kept));
  // With room, the next texts come whole, and no notice again.
  server.emit_numbered(kTexts, 3);
  EXPECT_EQ(client.output_lines(3, 5s),
            (std::vector<std::string>{"text 100000", "text 100001", "text 100002"}));
}

TEST(transport_tcp, PacerAdvancesVirtualTimeWithTheWallClock) {
  ServerFixture server;
  TestClient client(server.port());
  ASSERT_TRUE(client.send("now\n"));
  const auto before = std::stoull(client.line_answers().at(0).text);
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(300ms);
  ASSERT_TRUE(client.send("now\n"));
  const auto after = std::stoull(client.line_answers().at(0).text);
  const auto wall_us = std::chrono::duration_cast<std::chrono::microseconds>(
                           std::chrono::steady_clock::now() - start)
                           .count();
  EXPECT_GE(after - before, 250'000u);
  EXPECT_LE(after - before, static_cast<unsigned long long>(wall_us) + 20'000u);
}

TEST(transport_endpoint, AcceptsHostPortForms) {
  boost::asio::ip::tcp::endpoint endpoint;
  std::string error;
  ASSERT_TRUE(parse_endpoint("127.0.0.1:5000", endpoint, error));
  EXPECT_EQ(endpoint.port(), 5000);
  ASSERT_TRUE(parse_endpoint("7000", endpoint, error));
  EXPECT_EQ(endpoint.address().to_string(), "127.0.0.1");
  ASSERT_TRUE(parse_endpoint("[::1]:0", endpoint, error));
  EXPECT_TRUE(endpoint.address().is_v6());
  EXPECT_FALSE(parse_endpoint("localhost:x", endpoint, error));
  EXPECT_FALSE(parse_endpoint("1.2.3.4:70000", endpoint, error));
  EXPECT_FALSE(parse_endpoint("nohost:80", endpoint, error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace uprog::transport
