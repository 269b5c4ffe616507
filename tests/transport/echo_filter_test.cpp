// Taking a drive's echo out of its answers: the echo of each expression comes before its answer
// (MAN-SIMSW 3.2: "The echo is immediate, per each received character").
#include "transport/echo_filter.h"

#include <gtest/gtest.h>

namespace uprog::transport {
namespace {

std::string filtered(EchoFilter& filter, std::string_view sent, std::string_view received) {
  filter.expect(sent, ";\r\n");
  std::string out;
  // Byte by byte, as a slow serial line delivers it: the result must not depend on chunking.
  for (const char c : received) filter.feed(std::string_view(&c, 1), out);
  return out;
}

TEST(transport_echo_filter, TakesTheEchoOutOfInterleavedAnswers) {
  EchoFilter filter;
  EXPECT_EQ(filtered(filter, "PX;MO\r", "PX;1234;MO\r1;"), "1234;1;");
  EXPECT_TRUE(filter.echo_seen());
}

TEST(transport_echo_filter, PassesAnswersOfADriveThatDoesNotEcho) {
  EchoFilter filter;
  EXPECT_EQ(filtered(filter, "PX;MO\r", "1234;1;"), "1234;1;");
  EXPECT_FALSE(filter.echo_seen());
  // An answer that begins like the line: the held bytes are the answer's.
  EXPECT_EQ(filtered(filter, "12+1\r", "13;"), "13;");
}

TEST(transport_echo_filter, AnErrorAnswerAndAnEmptyExpression) {
  EchoFilter filter;
  EXPECT_EQ(filtered(filter, "AC=-5;\r", std::string("AC=-5;\x15?;\r;", 11)),
            std::string("\x15?;;", 4));
}

TEST(transport_echo_filter, EchoTurnedOffByTheLineItself) {
  EchoFilter filter;
  // EO=0 is echoed (the echo was on when its bytes came); the next line is not.
  EXPECT_EQ(filtered(filter, "EO=0\r", "EO=0\r;"), ";");
  EXPECT_EQ(filtered(filter, "PX\r", "7;"), "7;");
  EXPECT_FALSE(filter.echo_seen());
}

TEST(transport_echo_filter, BytesAfterTheLineAreAnswers) {
  EchoFilter filter;
  EXPECT_EQ(filtered(filter, "PX\r", "PX\r7;extra;"), "7;extra;");
}

}  // namespace
}  // namespace uprog::transport
