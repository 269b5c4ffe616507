// `uprog dap`'s server fed hostile messages in a session of every registered dialect (its sample
// program launched, stopped on entry): a request with a wrong field gets a failed response to
// its seq (the Debug Adapter Protocol's Response: success false, a message), anything else an
// output event and nothing more; each time, a good request after it is still answered.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "debug/dap_server.h"
#include "dialects/registry.h"
#include "jsonrpc/framing.h"

namespace uprog::debug {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// Requests whose arguments are of the wrong type or out of range: each is refused.
const char* const kBadRequests[] = {
    R"({"seq":"x","type":"request","command":"initialize"})",
    R"({"seq":1.5,"type":"request","command":"threads"})",
    R"({"seq":901,"type":"request","command":5})",
    R"({"seq":902,"type":"request","command":"threads","arguments":[1]})",
    R"({"seq":903,"type":"request","command":"stackTrace","arguments":{"threadId":"1"}})",
    R"({"seq":904,"type":"request","command":"stackTrace","arguments":{"threadId":1e300}})",
    R"({"seq":905,"type":"request","command":"stackTrace","arguments":{"threadId":1,"levels":-1}})",
    R"({"seq":906,"type":"request","command":"setBreakpoints","arguments":{"source":5}})",
    R"({"seq":907,"type":"request","command":"setBreakpoints",
        "arguments":{"source":{"path":"p"},"breakpoints":[{"line":1e300}]}})",
    R"({"seq":908,"type":"request","command":"setBreakpoints",
        "arguments":{"source":{"path":"p"},"breakpoints":{"line":1}}})",
    R"({"seq":909,"type":"request","command":"setBreakpoints",
        "arguments":{"source":{"path":"p"},"lines":[-1]}})",
    R"({"seq":910,"type":"request","command":"setFunctionBreakpoints",
        "arguments":{"breakpoints":[{"name":3}]}})",
    R"({"seq":911,"type":"request","command":"setExceptionBreakpoints",
        "arguments":{"filters":[1]}})",
    R"({"seq":912,"type":"request","command":"scopes","arguments":{"frameId":"a"}})",
    R"({"seq":913,"type":"request","command":"variables","arguments":{"variablesReference":1.5}})",
    R"({"seq":914,"type":"request","command":"variables","arguments":{}})",
    R"({"seq":915,"type":"request","command":"setVariable",
        "arguments":{"variablesReference":1,"name":[],"value":"1"}})",
    R"({"seq":916,"type":"request","command":"evaluate","arguments":{"expression":{}}})",
    R"({"seq":917,"type":"request","command":"evaluate",
        "arguments":{"expression":"1","frameId":true}})",
    R"({"seq":918,"type":"request","command":"next","arguments":{"threadId":"1"}})",
    R"({"seq":919,"type":"request","command":"stepIn","arguments":{"singleThread":1}})",
    R"({"seq":920,"type":"request","command":"launch","arguments":{"program":5}})",
    R"({"seq":921,"type":"request","command":"attach","arguments":{"port":"x"}})",
    R"({"seq":922,"type":"request","command":"noSuchCommand"})",
};

// Messages that are no request: dropped, with an output event.
const char* const kNotRequests[] = {
    R"({"seq":1,"type":5,"command":"initialize"})",
    R"({"seq":1,"command":"initialize"})",
    R"({"seq":1,"type":"response","command":"initialize","success":true})",
    R"({"seq":1,"type":"event","event":"stopped"})",
    "[]",
    "null",
    "\"request\"",
    "{}",
    "not JSON {",
    "",
    "\xff\xfe",
};

struct Session {
  std::vector<json> out;
  jsonrpc::MessageReader reader;
  DapServer server;
  explicit Session(const dialect::Dialect& d)
      : server({[&d](const std::string&, const std::string&, std::string&) { return &d; }},
               [this](const std::string& framed) {
                 reader.feed(framed);
                 while (auto body = reader.next()) out.push_back(json::parse(*body));
               }) {}
  std::vector<json> send(const std::string& text) {
    out.clear();
    server.handle(text);
    return out;
  }
};

class DapHostile : public ::testing::TestWithParam<std::string> {
 protected:
  const dialect::Dialect& dialect() const { return *dialects::find(GetParam()); }
};

// After each hostile message the session answers a good request as before.
void expect_still_answering(Session& s) {
  const std::vector<json> out = s.send(R"({"seq":1000,"type":"request","command":"threads"})");
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out[0]["type"], "response");
  EXPECT_EQ(out[0]["request_seq"], 1000);
  EXPECT_TRUE(out[0]["success"]);
}

void expect_refused(Session& s, const std::string& text) {
  SCOPED_TRACE(text);
  const std::vector<json> out = s.send(text);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["type"], "response");
  EXPECT_FALSE(out[0]["success"]);
  EXPECT_TRUE(out[0]["message"].is_string());
  const json sent = json::parse(text, nullptr, false);
  const int64_t seq = sent["seq"].is_number_integer() ? sent["seq"].get<int64_t>() : 0;
  EXPECT_EQ(out[0]["request_seq"], seq);
  expect_still_answering(s);
}

void expect_dropped(Session& s, const std::string& text) {
  SCOPED_TRACE(text);
  const std::vector<json> out = s.send(text);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["type"], "event");
  EXPECT_EQ(out[0]["event"], "output");
  EXPECT_EQ(out[0]["body"]["category"], "stderr");
  expect_still_answering(s);
}

TEST_P(DapHostile, ALaunchedSessionAnswersOrDropsEveryHostileMessage) {
  const dialect::SampleProgram& sample = dialect().sample_program();
  const fs::path dir = fs::temp_directory_path() / ("uprog_dap_hostile_" + GetParam());
  fs::create_directories(dir);
  const fs::path program = dir / std::string(sample.file_name);
  std::ofstream(program) << sample.source;

  Session s(dialect());
  const json launch = {{"seq", 1},
                       {"type", "request"},
                       {"command", "launch"},
                       {"arguments",
                        {{"program", program.string()},
                         {"entry", std::string(sample.entry)},
                         {"stopOnEntry", true}}}};
  s.send(R"({"seq":0,"type":"request","command":"initialize","arguments":{}})");
  std::vector<json> out = s.send(launch.dump());
  ASSERT_FALSE(out.empty());
  ASSERT_TRUE(out[0]["success"]) << out[0].dump();
  s.send(R"({"seq":2,"type":"request","command":"configurationDone"})");

  for (const char* text : kBadRequests) expect_refused(s, text);
  for (const char* text : kNotRequests) expect_dropped(s, text);
  // Still stopped where it was: the stack is there to read.
  out = s.send(R"({"seq":3,"type":"request","command":"stackTrace","arguments":{"threadId":1}})");
  ASSERT_FALSE(out.empty());
  EXPECT_TRUE(out[0]["success"]) << out[0].dump();
  fs::remove_all(dir);
}

TEST_P(DapHostile, BeforeALaunchEveryHostileMessageIsAnsweredOrDropped) {
  Session s(dialect());
  for (const char* text : kBadRequests) {
    SCOPED_TRACE(text);
    const std::vector<json> out = s.send(text);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_FALSE(out[0]["success"]);
  }
  for (const char* text : kNotRequests) {
    SCOPED_TRACE(text);
    EXPECT_EQ(s.send(text).size(), 1u);
  }
  const std::vector<json> out =
      s.send(R"({"seq":5,"type":"request","command":"initialize","arguments":{}})");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0]["success"]);
}

std::vector<std::string> registered() {
  std::vector<std::string> names;
  for (const dialect::Dialect* d : dialects::all()) names.emplace_back(d->name());
  return names;
}

INSTANTIATE_TEST_SUITE_P(EveryDialect, DapHostile, ::testing::ValuesIn(registered()),
                         [](const auto& name) { return name.param; });

}  // namespace
}  // namespace uprog::debug
