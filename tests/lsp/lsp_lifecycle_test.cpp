// The server's lifecycle as LSP 3.17 orders it: nothing but initialize before initialize
// (ServerNotInitialized, -32002), the capabilities it answers with, shutdown, then exit with 0
// (1 when exit comes without shutdown).
#include <gtest/gtest.h>

#include "lsp_client.h"

namespace uprog::lsp {
namespace {

TEST(LspLifecycle, InitializeShutdownExit) {
  LspClient c;
  std::vector<json> out = c.request("textDocument/hover", {});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["error"]["code"], -32002);
  // A notification before initialize is dropped.
  EXPECT_TRUE(c.open("file:///w/a.ehl", "gold", "int x\n").is_null());

  const json init = c.initialize();
  EXPECT_EQ(init["id"], 2);
  const json& caps = init["result"]["capabilities"];
  EXPECT_EQ(caps["textDocumentSync"]["openClose"], true);
  EXPECT_EQ(caps["textDocumentSync"]["change"], 2);  // TextDocumentSyncKind.Incremental
  EXPECT_EQ(caps["positionEncoding"], "utf-16");
  EXPECT_EQ(init["result"]["serverInfo"]["name"], "uprog");

  out = c.request("initialize", {{"capabilities", json::object()}});
  EXPECT_EQ(out.at(0)["error"]["code"], -32600);  // only once
  out = c.request("no/such/method");
  EXPECT_EQ(out.at(0)["error"]["code"], -32601);

  out = c.request("shutdown", nullptr);
  EXPECT_TRUE(out.at(0).contains("result"));
  EXPECT_TRUE(out.at(0)["result"].is_null());
  out = c.request("textDocument/hover", {});
  EXPECT_EQ(out.at(0)["error"]["code"], -32600);  // after shutdown, InvalidRequest
  EXPECT_FALSE(c.server.done());
  c.notify("exit");
  EXPECT_TRUE(c.server.done());
  EXPECT_EQ(c.server.exit_code(), 0);
}

TEST(LspLifecycle, ExitWithoutShutdownIsExitCodeOne) {
  LspClient c;
  c.initialize();
  c.notify("exit");
  EXPECT_TRUE(c.server.done());
  EXPECT_EQ(c.server.exit_code(), 1);
}

TEST(LspLifecycle, Utf8PositionsWhenTheClientOffersThem) {
  LspClient c;
  const json init = c.initialize({{"general", {{"positionEncodings", {"utf-8", "utf-16"}}}}});
  EXPECT_EQ(init["result"]["capabilities"]["positionEncoding"], "utf-8");
}

}  // namespace
}  // namespace uprog::lsp
