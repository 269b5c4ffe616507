// The debugger on the D-series drive's PDL over the Debug Adapter Protocol
// (tests/transcripts/debug/programs/pdl_debug.pdl, its procedures in pdl/scale.h): the tasks as
// threads, a breakpoint in the included file, the call stack of hand-built procedure frames with
// their parameters and locals, the globals, PDL expressions, setting a local and a global, steps
// over and out of procedure calls, and a breakpoint's condition, hit count and log message.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "debug/dap_server.h"
#include "dialects/pdl/dialect.h"
#include "jsonrpc/framing.h"

namespace uprog::debug {
namespace {

using json = nlohmann::json;
const std::string kDir = UPROG_SOURCE_DIR "/tests/transcripts/debug/programs/";
const std::string kProgram = kDir + "pdl_debug.pdl";
const std::string kScale = kDir + "pdl/scale.h";
constexpr int64_t kTask1 = 2;  // a DAP thread id is the VM's thread + 1: task t is t + 1

struct Client {
  std::vector<json> out;
  jsonrpc::MessageReader reader;
  DapServer server{{[](const std::string&, const std::string&,
                       std::string&) -> const dialect::Dialect* { return &pdl::dialect(); }},
                   [this](const std::string& framed) {
                     reader.feed(framed);
                     while (auto body = reader.next()) out.push_back(json::parse(*body));
                   }};
  int64_t seq = 1;

  std::vector<json> request(const std::string& command, json arguments = json::object()) {
    out.clear();
    const json r = {
        {"seq", seq++}, {"type", "request"}, {"command", command}, {"arguments", arguments}};
    server.handle(r.dump());
    return out;
  }
  json body(const std::string& command, json arguments = json::object()) {
    const auto r = request(command, std::move(arguments));
    EXPECT_FALSE(r.empty());
    EXPECT_TRUE(r.at(0)["success"]) << r.at(0).dump();
    return r.at(0)["body"];
  }
  std::vector<json> run() {
    out.clear();
    for (int i = 0; i < 1000 && server.poll(100'000'000); ++i) {
    }
    return out;
  }
  json stopped() {
    for (const json& m : run())
      if (m["type"] == "event" && m["event"] == "stopped") return m["body"];
    ADD_FAILURE() << "no stopped event";
    return json::object();
  }
  void start(json breakpoints) {
    request("initialize", {{"adapterID", "uprog"}});
    request("launch", {{"program", kProgram}});
    body("setBreakpoints", {{"source", {{"path", kScale}}}, {"breakpoints", breakpoints}});
    request("configurationDone");
  }
  json frames(int64_t thread) { return body("stackTrace", {{"threadId", thread}})["stackFrames"]; }
  json variables(int64_t frame_id, const std::string& scope) {
    const json scopes = body("scopes", {{"frameId", frame_id}})["scopes"];
    for (const json& s : scopes)
      if (s["name"] == scope)
        return body("variables", {{"variablesReference", s["variablesReference"]}})["variables"];
    return json::array();
  }
  std::string value(int64_t frame_id, const std::string& scope, const std::string& name) {
    const json vars = variables(frame_id, scope);
    for (const json& v : vars)
      if (v["name"] == name) return v["value"];
    return "<none>";
  }
  std::string eval(int64_t frame_id, const std::string& expression) {
    const auto r = request(
        "evaluate", {{"expression", expression}, {"frameId", frame_id}, {"context", "watch"}});
    return r.at(0)["success"] ? r[0]["body"]["result"].get<std::string>() : "error";
  }
};

TEST(PdlDebugger, TheTasksAreTheThreads) {
  Client c;
  c.start(json::array({{{"line", 11}}}));
  c.stopped();
  const json threads = c.body("threads")["threads"];
  ASSERT_EQ(threads.size(), 3u);
  for (int t = 1; t <= 3; ++t) {
    EXPECT_EQ(threads[t - 1]["id"], kTask1 + t - 1);
    EXPECT_EQ(threads[t - 1]["name"], "task " + std::to_string(t));
  }
}

TEST(PdlDebugger, FramesOfProceduresWithTheirParametersAndLocals) {
  Client c;
  // scale.h:5 is twice's first command, called from scale's line 12, called from task 1's line 11
  c.start(json::array({{{"line", 5}}}));
  const json stop = c.stopped();
  EXPECT_EQ(stop["reason"], "breakpoint");
  EXPECT_EQ(stop["threadId"], kTask1);
  const json frames = c.frames(kTask1);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0]["name"], "twice");
  EXPECT_EQ(frames[0]["line"], 5);
  EXPECT_EQ(frames[1]["name"], "scale");
  EXPECT_EQ(frames[1]["line"], 12);
  EXPECT_EQ(frames[1]["source"]["name"], "scale.h");
  EXPECT_EQ(frames[2]["name"], "_t1");
  EXPECT_EQ(frames[2]["line"], 11);
  EXPECT_EQ(frames[2]["source"]["name"], "pdl_debug.pdl");
  const int64_t twice = frames[0]["id"], scale = frames[1]["id"], task = frames[2]["id"];
  const json locals = c.variables(scale, "Locals");
  ASSERT_EQ(locals.size(), 5u);  // v, k, res (parameters), prod, half (locals)
  EXPECT_EQ(locals[0]["name"], "v");
  EXPECT_EQ(locals[0]["value"], "1");
  EXPECT_EQ(locals[1]["value"], "3");
  EXPECT_EQ(locals[2]["name"], "res");
  EXPECT_EQ(locals[2]["type"], "long*");
  EXPECT_EQ(locals[2]["value"], "1");  // &total: total is the second word of the user memory
  EXPECT_EQ(locals[3]["name"], "prod");
  EXPECT_EQ(locals[3]["value"], "3");
  EXPECT_EQ(locals[4]["type"], "float");
  EXPECT_EQ(locals[4]["value"], "0.0");
  EXPECT_EQ(c.value(twice, "Locals", "x"), "3");
  EXPECT_EQ(c.value(twice, "Locals", "t"), "0");
  // out points at scale's prod: task 1's stack word, 0x1000 + its index there
  const int32_t out = std::stoi(c.value(twice, "Locals", "out"));
  EXPECT_EQ(out & ~0xFF, 0x1000);
  EXPECT_TRUE(c.variables(task, "Locals").empty());  // task code has no locals
  EXPECT_EQ(c.value(task, "Globals", "count"), "1");
  EXPECT_EQ(c.value(task, "Globals", "ratio"), "0.0");
  // PDL expressions in each frame: its own names, the globals, the drive's variables
  EXPECT_EQ(c.eval(twice, "x*2+count"), "7");
  EXPECT_EQ(c.eval(scale, "prod/2"), "1.5");
  EXPECT_EQ(c.eval(twice, "*out"), "3");
  EXPECT_EQ(c.eval(scale, "v = 1"), "1");
  EXPECT_EQ(c.eval(scale, "x"), "error");  // twice's, not scale's
  EXPECT_EQ(c.eval(task, "fclk"), c.eval(twice, "fclk"));
}

// examples/pdl/move_with_timeout.pdl: the move ends within its 2 s, so the `else do` branch runs
// and a breakpoint on its first command (line 20) stops there with result still 0.
TEST(PdlDebugger, ABreakpointOnTheFirstCommandOfABranch) {
  Client c;
  const std::string example = UPROG_SOURCE_DIR "/examples/pdl/move_with_timeout.pdl";
  c.request("initialize", {{"adapterID", "uprog"}});
  c.request("launch", {{"program", example}});
  c.body("setBreakpoints",
         {{"source", {{"path", example}}}, {"breakpoints", json::array({{{"line", 20}}})}});
  c.request("configurationDone");
  const json stop = c.stopped();
  EXPECT_EQ(stop["reason"], "breakpoint");
  const json frames = c.frames(kTask1);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames[0]["line"], 20);
  EXPECT_EQ(c.value(frames[0]["id"], "Globals", "result"), "0");
}

TEST(PdlDebugger, StepOverAndOutOfProcedureCalls) {
  Client c;
  c.start(json::array({{{"line", 12}}}));  // scale's call of twice
  c.stopped();
  c.request("next", {{"threadId", kTask1}});
  EXPECT_EQ(c.stopped()["reason"], "step");
  json frames = c.frames(kTask1);
  EXPECT_EQ(frames[0]["name"], "scale");
  EXPECT_EQ(frames[0]["line"], 13);  // over twice: its frame came and went
  EXPECT_EQ(c.value(frames[0]["id"], "Locals", "prod"), "6");
  c.request("stepOut", {{"threadId", kTask1}});
  c.stopped();
  frames = c.frames(kTask1);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0]["line"], 12);
  EXPECT_EQ(c.value(frames[0]["id"], "Globals", "total"), "6");
}

TEST(PdlDebugger, SetALocalAndAGlobalAndTheProgramUsesThem) {
  Client c;
  c.start(json::array({{{"line", 13}}}));
  c.stopped();
  const int64_t scale = c.frames(kTask1)[0]["id"];
  json scopes = c.body("scopes", {{"frameId", scale}})["scopes"];
  json r = c.body(
      "setVariable",
      {{"variablesReference", scopes[0]["variablesReference"]}, {"name", "prod"}, {"value", "40"}});
  EXPECT_EQ(r["value"], "40");
  EXPECT_FALSE(c.request("setVariable", {{"variablesReference", scopes[0]["variablesReference"]},
                                         {"name", "nosuch"},
                                         {"value", "1"}})
                   .at(0)["success"]);
  r = c.body(
      "setVariable",
      {{"variablesReference", scopes[1]["variablesReference"]}, {"name", "count"}, {"value", "9"}});
  EXPECT_EQ(r["value"], "9");
  c.body("setBreakpoints", {{"source", {{"path", kScale}}}, {"breakpoints", json::array()}});
  c.body("setBreakpoints",
         {{"source", {{"path", kProgram}}}, {"breakpoints", json::array({{{"line", 13}}})}});
  c.request("continue", {{"threadId", kTask1}});
  c.stopped();
  const int64_t task = c.frames(kTask1)[0]["id"];
  EXPECT_EQ(c.value(task, "Globals", "total"), "40");    // *res=prod stored the value set
  EXPECT_EQ(c.value(task, "Globals", "ratio"), "10.0");  // and the next line used it
  EXPECT_EQ(c.value(task, "Globals", "count"), "9");
  EXPECT_EQ(c.eval(task, "set count = count + 1"), "10");  // an assignment stays made
  EXPECT_EQ(c.value(task, "Globals", "count"), "10");
}

TEST(PdlDebugger, ConditionHitCountAndLogMessage) {
  Client c;
  c.start(json::array({{{"line", 11}, {"condition", "v > 2"}, {"hitCondition", "2"}},
                       {{"line", 13}, {"logMessage", "prod={prod} half={half}"}}}));
  std::vector<std::string> logged;
  bool stopped = false;
  for (const json& m : c.run()) {
    if (m["type"] == "event" && m["event"] == "output" && m["body"]["category"] == "console")
      logged.push_back(m["body"]["output"]);
    stopped = stopped || (m["type"] == "event" && m["event"] == "stopped");
  }
  ASSERT_TRUE(stopped);
  const int64_t scale = c.frames(kTask1)[0]["id"];
  EXPECT_EQ(c.eval(scale, "v"), "4");  // v = 3 was the first hit of the condition, 4 the second
  ASSERT_EQ(logged.size(), 3u);
  // before line 13 runs: prod is 2 * 3 * v, half not yet computed in this call's fresh frame
  EXPECT_EQ(logged[0], "prod=6 half=0.0\n");
  EXPECT_EQ(logged[2], "prod=18 half=0.0\n");
}

TEST(PdlDebugger, AFunctionBreakpointOnAProcedureAndOnALabel) {
  Client c;
  c.start(json::array());
  json r = c.body("setFunctionBreakpoints",
                  {{"breakpoints", json::array({{{"name", "twice"}}, {{"name", "nosuch"}}})}});
  ASSERT_EQ(r["breakpoints"].size(), 2u);
  EXPECT_TRUE(r["breakpoints"][0]["verified"]);
  EXPECT_EQ(r["breakpoints"][0]["line"], 5);  // its first command, past the prologue
  EXPECT_FALSE(r["breakpoints"][1]["verified"]);
  const json stop = c.stopped();
  EXPECT_EQ(stop["reason"], "function breakpoint");
  EXPECT_EQ(c.frames(kTask1)[0]["name"], "twice");
  // a global label is an entry routine of the image
  r = c.body("setFunctionBreakpoints", {{"breakpoints", json::array({{{"name", "_t2"}}})}});
  EXPECT_TRUE(r["breakpoints"][0]["verified"]);
  c.request("continue", {{"threadId", kTask1}});
  EXPECT_EQ(c.stopped()["threadId"], kTask1 + 1);
}

}  // namespace
}  // namespace uprog::debug
