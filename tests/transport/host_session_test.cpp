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

// A service that keeps a count per host: "count" answers how many lines this host has sent.
class CountingService final : public LineService {
 public:
  class Channel final : public LineChannel {
   public:
    std::vector<Reply> handle_line(std::string_view line) override {
      ++lines;
      if (line == "count") return {{std::to_string(lines), 0}};
      return {};
    }
    int lines = 0;
  };
  std::vector<Reply> handle_line(std::string_view) override { return {{"shared", 0}}; }
  void advance(std::uint32_t) override {}
  const dialect::WireForm& wire() const override { return testing::semicolon_wire(); }
  std::unique_ptr<LineChannel> open_channel() override {
    ++opened;
    return std::make_unique<Channel>();
  }
  int opened = 0;
};

TEST(transport_host_session, EachHostHasItsOwnChannelDroppedOnDisconnect) {
  CountingService service;
  HostSession first(service), second(service);
  EXPECT_EQ(service.opened, 2);
  std::string out;
  first.receive("a;b;count;", out);
  second.receive("count;", out);
  EXPECT_EQ(out, ";;3;1;");
  first.disconnect();  // the host went away: what the service kept for it goes too
  EXPECT_EQ(service.opened, 3);
  out.clear();
  first.receive("count;", out);
  EXPECT_EQ(out, "1;");
}

}  // namespace
}  // namespace uprog::transport
