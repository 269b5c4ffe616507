// Answers on the wire: the server's form and the host-side reader agree.
#include "transport/reply.h"

#include <gtest/gtest.h>

#include "transport/answer_reader.h"

namespace uprog::transport {
namespace {

std::string wire_reply(const Reply& reply) {
  std::string out;
  dialect::append_semicolon_answer(reply, out);
  return out;
}

Reply parse_wire_reply(std::string_view answer) { return dialect::parse_semicolon_answer(answer); }

TEST(transport_reply, ValueErrorAndSilentForms) {
  EXPECT_EQ(wire_reply({"4", 0}), "4;");
  EXPECT_EQ(wire_reply({"", 0}), ";");
  EXPECT_EQ(wire_reply({"Operand out of range", 21}), "?21 Operand out of range;");
  EXPECT_EQ(wire_reply({"", 21}), "?21;");
}

TEST(transport_reply, TextCannotBreakTheFrame) {
  EXPECT_EQ(wire_reply({"a;b\r\nc", 0}), "a b  c;");
  EXPECT_EQ(wire_reply({"?x", 0}), " ?x;");  // a value never reads as an error
}

TEST(transport_reply, ParseReadsWhatWasWritten) {
  EXPECT_EQ(parse_wire_reply("?21 Operand out of range"), (Reply{"Operand out of range", 21}));
  EXPECT_EQ(parse_wire_reply("?900"), (Reply{"", 900}));
  EXPECT_EQ(parse_wire_reply("3.600000"), (Reply{"3.600000", 0}));
  EXPECT_EQ(parse_wire_reply("?"), (Reply{"", -1}));
}

TEST(transport_answer_reader, TextEndedByALineBreakIsTheDrivesOwnOutput) {
  AnswerReader reader;
  std::vector<AnswerEvent> events;
  reader.feed("7;\r\n%P 1 00000000 00000000 MSG A\r\n8;", events);
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0].reply, (Reply{"7", 0}));
  EXPECT_TRUE(events[1].end_of_line);
  EXPECT_TRUE(events[2].output);
  EXPECT_FALSE(events[2].end_of_line);
  EXPECT_EQ(events[2].reply.text, "%P 1 00000000 00000000 MSG A");
  EXPECT_EQ(events[3].reply, (Reply{"8", 0}));
  EXPECT_FALSE(events[3].output);
}

TEST(transport_answer_reader, SplitsAnswersAndLineEnds) {
  AnswerReader reader;
  std::vector<AnswerEvent> events;
  reader.feed(";4", events);
  EXPECT_EQ(events.size(), 1u);
  EXPECT_EQ(reader.partial(), "4");
  reader.feed(";\r", events);
  reader.feed("\n?19 Command syntax error;\r\n", events);
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0].reply, (Reply{"", 0}));
  EXPECT_EQ(events[1].reply, (Reply{"4", 0}));
  EXPECT_TRUE(events[2].end_of_line);
  EXPECT_EQ(events[3].reply, (Reply{"Command syntax error", 19}));
  EXPECT_TRUE(events[4].end_of_line);
}

}  // namespace
}  // namespace uprog::transport
