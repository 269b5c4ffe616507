// The pseudo-terminal: opened directly and through socat, as a serial terminal program would.
#include <fcntl.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "server_fixture.h"
#include "test_client.h"

namespace uprog::transport {
namespace {

using namespace std::chrono_literals;

TEST(transport_pty, SlaveOpensAndServesLines) {
  testing::ServerFixture server(true);
  ASSERT_TRUE(server.pty_path().starts_with("/dev/pts/"));
  const int fd = ::open(server.pty_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  testing::TestClient terminal(fd, testing::TestClient::Adopt{});
  ASSERT_TRUE(terminal.send("PX=7; PX-3\r"));
  EXPECT_EQ(terminal.line_answers(), (std::vector<Reply>{{"PX=7", 0}, {"PX-3", 0}}));
  ASSERT_TRUE(terminal.send(std::string("a\0b\r", 4)));
  EXPECT_EQ(terminal.line_answers(), (std::vector<Reply>{{"Bad character", kErrorBadCharacter}}));
}

TEST(transport_pty, SocatTalksToTheSlave) {
  testing::ServerFixture server(true);
  const std::string command =
      "printf 'two;err 19\\r' | timeout 10 socat -t 1 - " + server.pty_path() + ",raw,echo=0 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  EXPECT_EQ(status, 0) << output;
  EXPECT_EQ(output, "1;2;?19 Failed;\r\n");
}

}  // namespace
}  // namespace uprog::transport
