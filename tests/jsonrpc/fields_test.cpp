// Checked field access: each reader takes its own type only, and an integer only inside its
// range; absent and null fields take the fallback.
#include "jsonrpc/fields.h"

#include <gtest/gtest.h>

namespace uprog::jsonrpc {
namespace {

TEST(Fields, ReadersTakeTheirOwnTypeOnly) {
  const json o = json::parse(R"({"s":"text","i":7,"b":true,"f":1.5,"n":null,"a":[1,2],
                                 "o":{"k":1},"big":18446744073709551615,"neg":-3})");
  EXPECT_EQ(string_or(o, "s", "x"), "text");
  EXPECT_EQ(string_or(o, "n", "x"), "x");  // null is absent
  EXPECT_EQ(string_or(o, "missing", "x"), "x");
  EXPECT_THROW(string_or(o, "i", "x"), FieldError);
  EXPECT_EQ(integer_or(o, "i", 0), 7);
  EXPECT_THROW(integer_or(o, "f", 0), FieldError);  // 1.5 is no integer
  EXPECT_THROW(integer_or(o, "s", 0), FieldError);
  EXPECT_THROW(integer_or(o, "big", 0), FieldError);  // above INT64_MAX
  EXPECT_THROW(integer_or(o, "neg", 0, 0), FieldError);
  EXPECT_THROW(integer_or(o, "i", 0, 0, 6), FieldError);
  EXPECT_TRUE(bool_or(o, "b", false));
  EXPECT_THROW(bool_or(o, "i", false), FieldError);
  EXPECT_EQ(number_or(o, "i", 0), 7.0);
  EXPECT_THROW(number_or(o, "s", 0), FieldError);
  EXPECT_EQ(object_or_empty(o, "o").size(), 1u);
  EXPECT_TRUE(object_or_empty(o, "missing").empty());
  EXPECT_THROW(object_or_empty(o, "a"), FieldError);
  EXPECT_THROW(required_object(o, "missing"), FieldError);
  EXPECT_EQ(numbers_or_empty(o, "a"), (std::vector<double>{1, 2}));
  EXPECT_THROW(strings_or_empty(o, "a"), FieldError);
  EXPECT_THROW(required_string(o, "missing"), FieldError);
}

TEST(Fields, AMessageThatIsNoObjectIsAFieldError) {
  EXPECT_THROW(string_or(json::array(), "s", ""), FieldError);
  EXPECT_THROW(integer_or(json(5), "i", 0), FieldError);
  EXPECT_EQ(find(json("x"), "s"), nullptr);  // find and peek never throw
  EXPECT_EQ(peek_string(json::parse(R"({"s":5})"), "s"), std::nullopt);
}

TEST(Fields, TheErrorNamesTheField) {
  try {
    (void)required_integer(json::parse(R"({"line":"3"})"), "line");
    FAIL();
  } catch (const FieldError& e) {
    EXPECT_EQ(std::string(e.what()), "line: expected an integer");
  }
}

TEST(Fields, TextOfInvalidUtf8IsReplacedNotThrown) {
  const json m = {{"output", std::string("a\xff")}};
  EXPECT_EQ(to_text(m), "{\"output\":\"a\xEF\xBF\xBD\"}");  // U+FFFD
}

}  // namespace
}  // namespace uprog::jsonrpc
