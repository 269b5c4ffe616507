// The DAP server's protocol: framed requests in, and the ordered responses and events out, as
// the Debug Adapter Protocol specifies them. Deterministic, because virtual time is.
#include "debug/dap_server.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "dialects/gold/dialect.h"
#include "jsonrpc/framing.h"

namespace uprog::debug {
namespace {

using json = nlohmann::json;
const std::string kScenario = UPROG_SOURCE_DIR "/tests/debug/programs/scenario.ehl";

struct Client {
  std::vector<json> out;
  jsonrpc::MessageReader reader;
  DapServer server{{[](const std::string& name, const std::string&,
                       std::string& error) -> const dialect::Dialect* {
                     if (name.empty() || name == "gold") return &gold::dialect();
                     error = "no dialect named '" + name + "'";
                     return nullptr;
                   }},
                   [this](const std::string& framed) {
                     reader.feed(framed);
                     while (auto body = reader.next()) out.push_back(json::parse(*body));
                   }};
  int64_t seq = 1;

  std::vector<json> request(const std::string& command, json arguments = json::object()) {
    out.clear();
    const json r = {
        {"seq", seq++}, {"type", "request"}, {"command", command}, {"arguments", arguments}};
    server.handle(r.dump(-1, ' ', false, json::error_handler_t::replace));
    return out;
  }
  // Lets the program run until it stops or ends: the events that came.
  std::vector<json> run() {
    out.clear();
    for (int i = 0; i < 1000 && server.poll(100'000'000); ++i) {
    }
    return out;
  }
  // initialize, launch, the given breakpoints, configurationDone: what configurationDone brought.
  std::vector<json> start(json launch, std::vector<uint32_t> lines = {}, bool errors = false) {
    request("initialize", {{"adapterID", "uprog"}});
    launch["program"] = kScenario;
    request("launch", launch);
    json bps = json::array();
    for (uint32_t l : lines) bps.push_back({{"line", l}});
    request("setBreakpoints", {{"source", {{"path", kScenario}}}, {"breakpoints", bps}});
    request("setExceptionBreakpoints",
            {{"filters", errors ? json::array({"error"}) : json::array()}});
    return request("configurationDone");
  }
  json frame_variables(int64_t frame_id, const std::string& scope) {
    const auto scopes = request("scopes", {{"frameId", frame_id}});
    for (const json& s : scopes.at(0)["body"]["scopes"]) {
      if (s["name"] == scope)
        return request("variables", {{"variablesReference", s["variablesReference"]}})
            .at(0)["body"]["variables"];
    }
    return json::array();
  }
  std::string value_of(int64_t frame_id, const std::string& scope, const std::string& name) {
    for (const json& v : frame_variables(frame_id, scope))
      if (v["name"] == name) return v["value"];
    return "<none>";
  }
  json top_frame() {
    return request("stackTrace", {{"threadId", 1}}).at(0)["body"]["stackFrames"].at(0);
  }
};

std::vector<std::string> kinds(const std::vector<json>& messages) {
  std::vector<std::string> out;
  for (const json& m : messages)
    out.push_back(m["type"] == "event" ? "event " + m["event"].get<std::string>()
                                       : "response " + m["command"].get<std::string>());
  return out;
}

TEST(DapServer, InitializeAnswersTheCapabilities) {
  Client c;
  const auto out = c.request("initialize", {{"adapterID", "uprog"}});
  ASSERT_EQ(kinds(out), std::vector<std::string>{"response initialize"});
  const json& r = out[0];
  EXPECT_EQ(r["request_seq"], 1);
  EXPECT_TRUE(r["success"]);
  for (const char* cap : {"supportsConfigurationDoneRequest", "supportsFunctionBreakpoints",
                          "supportsConditionalBreakpoints", "supportsHitConditionalBreakpoints",
                          "supportsLogPoints", "supportsSetVariable", "supportsTerminateRequest"}) {
    EXPECT_TRUE(r["body"][cap]) << cap;
  }
  EXPECT_EQ(r["body"]["exceptionBreakpointFilters"][0]["filter"], "error");
}

TEST(DapServer, LaunchThenInitializedThenBreakpointStop) {
  Client c;
  c.request("initialize");
  auto out = c.request("launch", {{"program", kScenario}});
  // The drive's log follows: the program downloaded and started.
  EXPECT_EQ(kinds(out), (std::vector<std::string>{"response launch", "event initialized",
                                                  "event thread", "event output", "event output"}));
  EXPECT_NE(out[4]["body"]["output"].get<std::string>().find("program started at main"),
            std::string::npos);
  EXPECT_TRUE(out[0]["success"]);
  EXPECT_EQ(out[2]["body"]["reason"], "started");
  EXPECT_EQ(out[2]["body"]["threadId"], 1);
  out = c.request("setBreakpoints", {{"source", {{"path", kScenario}}},
                                     {"breakpoints", {{{"line", 19}}, {{"line", 16}}}}});
  ASSERT_EQ(kinds(out), std::vector<std::string>{"response setBreakpoints"});
  const json bps = out[0]["body"]["breakpoints"];
  ASSERT_EQ(bps.size(), 2u);
  EXPECT_TRUE(bps[0]["verified"]);
  EXPECT_EQ(bps[0]["line"], 19);
  EXPECT_EQ(bps[1]["line"], 18);  // moved to the next line with code
  // Nothing runs before configurationDone.
  EXPECT_TRUE(c.run().empty());
  out = c.request("configurationDone");
  EXPECT_EQ(kinds(out), std::vector<std::string>{"response configurationDone"});
  out = c.run();
  // The first hit is line 18 (the moved breakpoint), then 19.
  ASSERT_EQ(kinds(out), std::vector<std::string>{"event stopped"});
  EXPECT_EQ(out[0]["body"]["reason"], "breakpoint");
  EXPECT_EQ(out[0]["body"]["threadId"], 1);
  EXPECT_EQ(out[0]["body"]["allThreadsStopped"], true);
  EXPECT_EQ(out[0]["body"]["hitBreakpointIds"], json::array({bps[1]["id"]}));
  EXPECT_EQ(c.top_frame()["line"], 18);
  out = c.request("continue", {{"threadId", 1}});
  ASSERT_EQ(kinds(out), std::vector<std::string>{"response continue"});
  EXPECT_TRUE(out[0]["body"]["allThreadsContinued"]);
  out = c.run();
  ASSERT_EQ(kinds(out), std::vector<std::string>{"event stopped"});
  EXPECT_EQ(out[0]["body"]["hitBreakpointIds"], json::array({bps[0]["id"]}));
}

TEST(DapServer, ThreadsStackScopesAndVariables) {
  Client c;
  c.start(json::object(), {19});
  c.run();
  auto out = c.request("threads");
  EXPECT_EQ(out.at(0)["body"]["threads"], json::parse(R"([{"id":1,"name":"program"}])"));
  out = c.request("stackTrace", {{"threadId", 1}});
  const json frames = out.at(0)["body"]["stackFrames"];
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(out[0]["body"]["totalFrames"], 2);
  EXPECT_EQ(frames[0]["name"], "add");
  EXPECT_EQ(frames[0]["line"], 19);
  EXPECT_EQ(frames[0]["source"]["name"], "scenario.ehl");
  EXPECT_EQ(frames[1]["name"], "main");
  EXPECT_EQ(frames[1]["line"], 11);
  const int64_t add = frames[0]["id"], main = frames[1]["id"];
  EXPECT_EQ(c.value_of(add, "Locals", "a"), "0");
  EXPECT_EQ(c.value_of(add, "Locals", "b"), "1");
  EXPECT_EQ(c.value_of(add, "Locals", "c"), "1");
  EXPECT_EQ(c.value_of(main, "Locals", "i"), "1");
  EXPECT_EQ(c.value_of(add, "Globals", "divisor"), "4");
  EXPECT_EQ(c.value_of(add, "Globals", "ratio"), "0.0");
  EXPECT_EQ(c.value_of(add, "Drive", "position"), "0");
  // levels and startFrame
  out = c.request("stackTrace", {{"threadId", 1}, {"startFrame", 1}, {"levels", 1}});
  ASSERT_EQ(out.at(0)["body"]["stackFrames"].size(), 1u);
  EXPECT_EQ(out[0]["body"]["stackFrames"][0]["name"], "main");
  // a reference from before the program ran on is gone
  c.request("next", {{"threadId", 1}});
  c.run();
  out = c.request("variables", {{"variablesReference", 1}});
  EXPECT_FALSE(out.at(0)["success"]);
}

TEST(DapServer, EvaluateInTheDialectAndOnTheCommandLine) {
  Client c;
  c.start(json::object(), {19});
  c.run();
  const int64_t add = c.top_frame()["id"];
  auto out =
      c.request("evaluate", {{"expression", "a + b * 10"}, {"frameId", add}, {"context", "hover"}});
  EXPECT_EQ(out.at(0)["body"]["result"], "10");
  out = c.request("evaluate", {{"expression", "a +"}, {"frameId", add}, {"context", "watch"}});
  EXPECT_FALSE(out.at(0)["success"]);
  // repl: a line of the drive's command line (Gold's), where the program's globals are known
  out = c.request("evaluate", {{"expression", "divisor*2; PS"}, {"context", "repl"}});
  EXPECT_EQ(out.at(0)["body"]["result"],
            "8\n0");  // PS is 0: the program does not run while stopped
}

TEST(DapServer, SetVariableAndTheProgramUsesIt) {
  Client c;
  c.start(json::object(), {13});
  c.run();
  const int64_t main = c.top_frame()["id"];
  const auto scopes = c.request("scopes", {{"frameId", main}}).at(0)["body"]["scopes"];
  const json globals = scopes[1]["variablesReference"];
  auto out = c.request("setVariable",
                       {{"variablesReference", globals}, {"name", "divisor"}, {"value", "8"}});
  EXPECT_TRUE(out.at(0)["success"]);
  EXPECT_EQ(out[0]["body"]["value"], "8");
  out = c.request("setVariable",
                  {{"variablesReference", globals}, {"name", "divisor"}, {"value", "x"}});
  EXPECT_FALSE(out.at(0)["success"]);
  out = c.request("setVariable", {{"variablesReference", scopes[2]["variablesReference"]},
                                  {"name", "position"},
                                  {"value", "1"}});
  EXPECT_FALSE(out.at(0)["success"]);  // the drive's signals are read-only
  c.request("continue", {{"threadId", 1}});
  out = c.run();
  EXPECT_EQ(kinds(out), (std::vector<std::string>{"event output", "event thread", "event exited",
                                                  "event terminated"}));
  EXPECT_EQ(out[2]["body"]["exitCode"], 0);
  EXPECT_EQ(
      c.request("evaluate", {{"expression", "ratio"}, {"context", "repl"}}).at(0)["body"]["result"],
      "12.0");  // Gold's form of a whole float
}

TEST(DapServer, StepsAndStopOnEntry) {
  Client c;
  auto out = c.start({{"stopOnEntry", true}});
  ASSERT_EQ(kinds(out), (std::vector<std::string>{"response configurationDone", "event stopped"}));
  EXPECT_EQ(out[1]["body"]["reason"], "entry");
  EXPECT_TRUE(c.run().empty());  // stopped: nothing runs
  EXPECT_EQ(c.top_frame()["line"], 9);
  struct Step {
    const char* request;
    int line;
    const char* routine;
  };
  for (const Step& s :
       {Step{"next", 10, "main"}, Step{"next", 11, "main"}, Step{"stepIn", 18, "add"},
        Step{"next", 19, "add"}, Step{"stepOut", 12, "main"}}) {
    out = c.request(s.request, {{"threadId", 1}});
    ASSERT_EQ(kinds(out), std::vector<std::string>{std::string("response ") + s.request});
    out = c.run();
    ASSERT_EQ(kinds(out), std::vector<std::string>{"event stopped"}) << s.request;
    EXPECT_EQ(out[0]["body"]["reason"], "step");
    EXPECT_EQ(c.top_frame()["line"], s.line) << s.request;
    EXPECT_EQ(c.top_frame()["name"], s.routine) << s.request;
  }
  // stepping while running is refused
  c.request("continue", {{"threadId", 1}});
  out = c.request("next", {{"threadId", 1}});
  EXPECT_FALSE(out.at(0)["success"]);
}

TEST(DapServer, ConditionsHitCountsAndLogPoints) {
  Client c;
  c.request("initialize");
  c.request("launch", {{"program", kScenario}});
  auto out = c.request("setBreakpoints", {{"source", {{"path", kScenario}}},
                                          {"breakpoints",
                                           {{{"line", 11}, {"hitCondition", "%2"}},
                                            {{"line", 19}, {"logMessage", "c is {c}"}},
                                            {{"line", 13}, {"condition", "total == 15"}},
                                            {{"line", 18}, {"hitCondition", "bad"}}}}});
  const json bps = out.at(0)["body"]["breakpoints"];
  EXPECT_FALSE(bps[3]["verified"]);
  EXPECT_TRUE(bps[3].contains("message"));
  c.request("configurationDone");
  std::vector<std::string> seen;
  for (int i = 0; i < 10; ++i) {
    out = c.run();
    for (const json& m : out) {
      if (m["event"] == "output") {
        // The drive's log lines start with their time; the text after it is what matters here.
        const std::string text = m["body"]["output"];
        seen.push_back("output " + (text[0] == '[' ? text.substr(text.find(']') + 2) : text));
      }
      if (m["event"] == "stopped")
        seen.push_back("stopped " + std::to_string(c.top_frame()["line"].get<int>()));
      if (m["event"] == "terminated") seen.push_back("terminated");
    }
    if (!seen.empty() && seen.back() == "terminated") break;
    c.request("continue", {{"threadId", 1}});
  }
  const std::vector<std::string> expected = {
      "output c is 1\n",
      "stopped 11",  // the 2nd hit of line 11: i = 2, before its call
      "output c is 3\n",
      "output c is 6\n",
      "stopped 11",
      "output c is 10\n",
      "output c is 15\n",
      "stopped 13",  // total == 15 there
      "output program finished\n",
      "terminated"};
  EXPECT_EQ(seen, expected);
}

TEST(DapServer, FunctionBreakpointAndBreakOnError) {
  Client c;
  c.start(json::object(), {}, true);
  auto out = c.request("setFunctionBreakpoints",
                       {{"breakpoints", {{{"name", "add"}}, {{"name", "nothere"}}}}});
  EXPECT_TRUE(out.at(0)["body"]["breakpoints"][0]["verified"]);
  EXPECT_FALSE(out[0]["body"]["breakpoints"][1]["verified"]);
  out = c.run();
  ASSERT_EQ(kinds(out), std::vector<std::string>{"event stopped"});
  EXPECT_EQ(out[0]["body"]["reason"], "function breakpoint");
  c.request("setFunctionBreakpoints", {{"breakpoints", json::array()}});
  c.request("evaluate", {{"expression", "divisor = 0"}, {"context", "repl"}});
  c.request("continue", {{"threadId", 1}});
  out = c.run();
  // The drive's log says what happened, then the stop.
  ASSERT_EQ(kinds(out), (std::vector<std::string>{"event output", "event stopped"}));
  EXPECT_NE(out[0]["body"]["output"].get<std::string>().find("run-time error"), std::string::npos);
  EXPECT_EQ(out[1]["body"]["reason"], "exception");
  EXPECT_NE(out[1]["body"]["description"].get<std::string>().find("ivision"), std::string::npos);
  EXPECT_EQ(c.top_frame()["line"], 13);
  c.request("continue", {{"threadId", 1}});
  out = c.run();
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back()["event"], "terminated");
  EXPECT_EQ(out[out.size() - 2]["body"]["exitCode"], 1);
}

TEST(DapServer, PauseStopsARunningProgram) {
  Client c;
  c.start(json::object());
  auto out = c.request("pause", {{"threadId", 1}});
  ASSERT_EQ(kinds(out), (std::vector<std::string>{"response pause", "event stopped"}));
  EXPECT_EQ(out[1]["body"]["reason"], "pause");
}

TEST(DapServer, ALineThatResumesTheProgramSendsContinued) {
  Client c;
  c.start(json::object(), {19});
  c.run();
  // A line that does not resume it: no event.
  auto out = c.request("evaluate", {{"expression", "PS"}, {"context", "repl"}});
  EXPECT_EQ(kinds(out), std::vector<std::string>{"response evaluate"});
  // Gold's XC, typed at the drive's command line, continues the program: the client is told.
  c.request("setBreakpoints", {{"source", {{"path", kScenario}}}, {"breakpoints", json::array()}});
  out = c.request("evaluate", {{"expression", "XC"}, {"context", "repl"}});
  ASSERT_GE(out.size(), 2u);
  EXPECT_EQ(kinds(out)[0], "response evaluate");
  EXPECT_EQ(kinds(out)[1], "event continued");
  EXPECT_EQ(out[1]["body"]["allThreadsContinued"], true);
  // Stepping is refused now: it runs.
  EXPECT_FALSE(c.request("next", {{"threadId", 1}}).at(0)["success"]);
  out = c.run();
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back()["event"], "terminated");
}

TEST(DapServer, BadRequestsGetErrorsAndTheSessionGoesOn) {
  Client c;
  auto out = c.request("setBreakpoints", {{"source", {{"path", kScenario}}}});
  EXPECT_FALSE(out.at(0)["success"]);  // before launch
  out = c.request("launch", json::object());
  EXPECT_FALSE(out.at(0)["success"]);
  EXPECT_NE(out[0]["message"].get<std::string>().find("program"), std::string::npos);
  out = c.request("launch", {{"program", "/nonexistent.ehl"}});
  EXPECT_FALSE(out.back()["success"]);
  out = c.request("launch", {{"program", kScenario}, {"dialect", "klingon"}});
  EXPECT_FALSE(out.at(0)["success"]);
  out = c.request("launch", {{"program", kScenario}, {"inputs", {"9=1@1ms"}}});
  EXPECT_FALSE(out.at(0)["success"]);
  out = c.request("launch",
                  {{"program", kScenario}, {"stopOnEntry", "yes"}});  // a string, not a bool
  EXPECT_FALSE(out.at(0)["success"]);
  out = c.request("frobnicate");
  EXPECT_FALSE(out.at(0)["success"]);
  c.out.clear();
  c.server.handle("{not json");
  ASSERT_EQ(kinds(c.out), std::vector<std::string>{"event output"});
  EXPECT_EQ(c.out[0]["body"]["category"], "stderr");
  out = c.request("launch", {{"program", kScenario}});
  EXPECT_TRUE(out.at(0)["success"]);
  out = c.request("stackTrace", {{"threadId", "one"}});
  EXPECT_FALSE(out.at(0)["success"]);
}

TEST(DapServer, TerminateThenDisconnect) {
  Client c;
  c.start(json::object(), {11});
  c.run();
  auto out = c.request("terminate");
  EXPECT_EQ(kinds(out), (std::vector<std::string>{"response terminate", "event terminated"}));
  EXPECT_FALSE(c.server.done());
  out = c.request("disconnect");
  EXPECT_EQ(kinds(out), std::vector<std::string>{"response disconnect"});
  EXPECT_TRUE(c.server.done());
}

}  // namespace
}  // namespace uprog::debug

namespace uprog::debug {
namespace {

// Requests of every command with arguments of every shape, and bytes that are not UTF-8: each
// gets an answer or an error event, and the session goes on answering.
TEST(DapServer, ArbitraryRequestsNeverEndTheSession) {
  const std::vector<std::string> commands = {"initialize",
                                             "launch",
                                             "setBreakpoints",
                                             "setFunctionBreakpoints",
                                             "setExceptionBreakpoints",
                                             "configurationDone",
                                             "threads",
                                             "stackTrace",
                                             "scopes",
                                             "variables",
                                             "setVariable",
                                             "evaluate",
                                             "continue",
                                             "next",
                                             "stepIn",
                                             "stepOut",
                                             "pause",
                                             "attach",
                                             "bogus"};
  const std::vector<json> values = {nullptr,
                                    0,
                                    -1,
                                    99999999999,
                                    2.5,
                                    "x",
                                    "\xff\xfe",
                                    json::array(),
                                    json::array({1, "a"}),
                                    json::object(),
                                    true,
                                    {{"line", "a"}},
                                    {{"path", kScenario}},
                                    json::array({{{"line", -3}}})};
  const std::vector<std::string> keys = {"program",
                                         "source",
                                         "breakpoints",
                                         "lines",
                                         "threadId",
                                         "frameId",
                                         "variablesReference",
                                         "name",
                                         "value",
                                         "expression",
                                         "context",
                                         "filters",
                                         "inputs",
                                         "args",
                                         "stopOnEntry",
                                         "levels",
                                         "startFrame"};
  std::mt19937 random(16);
  Client c;
  c.start(json::object(), {11});
  c.run();
  for (int i = 0; i < 3000; ++i) {
    json args = json::object();
    const int n = static_cast<int>(random() % 4);
    for (int k = 0; k < n; ++k)
      args[keys[random() % keys.size()]] = values[random() % values.size()];
    const auto out = c.request(commands[random() % commands.size()], args);
    ASSERT_FALSE(out.empty()) << i;
    c.run();
  }
  c.out.clear();
  c.server.handle("\xff\xfe{");
  c.server.handle(R"({"seq": 1, "type": "request", "command": 7})");
  EXPECT_EQ(c.out.size(), 2u);
  const auto out = c.request("threads");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0]["success"]);
}

}  // namespace
}  // namespace uprog::debug

namespace uprog::debug {
namespace {

// `uprog sim --dap`'s server: attach debugs the program the drive already runs, time passes
// through keep_time() (none while stopped, and the hosts' lines take none), and disconnect leaves
// the program running undebugged.
TEST(DapServer, AttachStopsTheDrivesRunningProgramAndItsTime) {
  const std::string program = UPROG_SOURCE_DIR "/tests/debug/programs/attach.ehl";
  controller::ControllerOptions o;
  o.dialect = &gold::dialect();
  controller::Controller drive(o);
  std::vector<Diagnostic> diagnostics;
  ASSERT_TRUE(drive.download_source_file(program, diagnostics));
  ASSERT_EQ(drive.start_program("main"), "");
  drive.advance(100'000);
  std::vector<json> out;
  jsonrpc::MessageReader reader;
  DapOptions options;
  options.attach_target = &drive;
  DapServer server(options, [&](const std::string& framed) {
    reader.feed(framed);
    while (auto body = reader.next()) out.push_back(json::parse(*body));
  });
  int64_t seq = 1;
  auto request = [&](const std::string& command, json arguments = json::object()) {
    out.clear();
    server.handle(
        json{{"seq", seq++}, {"type", "request"}, {"command", command}, {"arguments", arguments}}
            .dump());
    return out;
  };
  request("initialize", {{"adapterID", "uprog"}});
  EXPECT_EQ(kinds(request("launch", {{"program", program}})),
            std::vector<std::string>{"response launch"});
  EXPECT_FALSE(out.at(0)["success"]);
  EXPECT_EQ(kinds(request("attach", {{"host", "127.0.0.1"}, {"port", 4712}})),
            (std::vector<std::string>{"response attach", "event initialized", "event thread"}));
  EXPECT_TRUE(out.at(0)["success"]);
  request("setBreakpoints", {{"source", {{"path", program}}}, {"breakpoints", {{{"line", 10}}}}});
  EXPECT_TRUE(out.at(0)["body"]["breakpoints"][0]["verified"]);
  request("configurationDone");
  out.clear();
  for (int i = 0; i < 100 && out.empty(); ++i) EXPECT_TRUE(server.keep_time(1'000'000));
  ASSERT_EQ(kinds(out), std::vector<std::string>{"event stopped"});
  EXPECT_EQ(out[0]["body"]["reason"], "breakpoint");
  // Stopped: time stands, however long the pacer and the hosts go on.
  const uint64_t at = drive.now_us();
  auto host = drive.open_session();
  for (int i = 0; i < 10; ++i) {
    EXPECT_TRUE(server.keep_time(1'000'000));
    host->send("TM");
    server.after_host_line();
  }
  EXPECT_EQ(drive.now_us(), at);
  // Continue, with the breakpoint gone: time and the program go on.
  request("setBreakpoints", {{"source", {{"path", program}}}, {"breakpoints", json::array()}});
  EXPECT_EQ(kinds(request("continue", {{"threadId", 1}})),
            std::vector<std::string>{"response continue"});
  for (int i = 0; i < 50; ++i) EXPECT_TRUE(server.keep_time(1'000'000));
  EXPECT_EQ(drive.now_us(), at + 50'000);
  // Disconnect: the drive keeps its own time again, the program runs on.
  EXPECT_EQ(kinds(request("disconnect")), std::vector<std::string>{"response disconnect"});
  EXPECT_TRUE(server.done());
  EXPECT_FALSE(server.keep_time(1'000'000));
  EXPECT_TRUE(drive.program_running());
}

TEST(DapServer, AttachWithoutADriveSaysWhy) {
  Client c;
  c.request("initialize", {{"adapterID", "uprog"}});
  const auto out = c.request("attach", {{"host", "127.0.0.1"}, {"port", 1}});
  ASSERT_EQ(kinds(out), std::vector<std::string>{"response attach"});
  EXPECT_FALSE(out[0]["success"]);
  EXPECT_EQ(out[0]["message"], "attach: no drive to attach to here");
}

}  // namespace
}  // namespace uprog::debug
