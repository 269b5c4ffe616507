// A host's conversation without sockets: every line answered, in order, CR LF after a typed line.
#include "transport/host_session.h"

#include <gtest/gtest.h>

#include "fake_service.h"

namespace uprog::transport {
namespace {

std::string talk(std::string_view bytes) {
  testing::FakeService service;
  HostSession session(service);
  std::string out;
  session.receive(bytes, out);
  return out;
}

TEST(transport_host_session, AnswersEachExpressionAndEndsTheTypedLine) {
  EXPECT_EQ(talk("PX=7; PX-3\r\n"), "PX=7;PX-3;\r\n");
  EXPECT_EQ(talk("quiet\n"), ";\r\n");
  EXPECT_EQ(talk("two;err 21\n"), "1;2;?21 Failed;\r\n");
}

TEST(transport_host_session, SemicolonTerminatedLinesNeedNoLineBreak) {
  EXPECT_EQ(talk("a;b;"), "a;b;");
}

TEST(transport_host_session, CommentOnlyLineStillEndsWithLineBreak) {
  EXPECT_EQ(talk("** note\n\n"), "\r\n");
}

TEST(transport_host_session, FramingErrorsAreAnsweredWithTransportCodes) {
  EXPECT_EQ(talk(std::string(600, 'x') + "\nok\n"), "?900 Line too long;\r\nok;\r\n");
  EXPECT_EQ(talk(std::string("a\0b;ok;", 7)), "?901 Bad character;ok;");
}

TEST(transport_host_session, DisconnectDropsThePartialLine) {
  testing::FakeService service;
  HostSession session(service);
  std::string out;
  session.receive("half", out);
  session.disconnect();
  session.receive("whole;", out);
  EXPECT_EQ(out, "whole;");
  EXPECT_EQ(service.lines, 1u);
}

}  // namespace
}  // namespace uprog::transport
