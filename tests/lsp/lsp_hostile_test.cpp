// The language server fed hostile messages: a request with a wrong field gets a JSON-RPC error
// (jsonrpc.org/specification 5.1: -32700 parse error, -32600 invalid request, -32602 invalid
// params) to its id, anything else is dropped; after each, the server still checks a document.
#include <gtest/gtest.h>

#include "lsp_client.h"

namespace uprog::lsp {
namespace {

struct Hostile {
  const char* text;
  int code;  // the error's code; 0: dropped, nothing sent
};

const Hostile kHostile[] = {
    {"{", -32700},
    {"", -32700},
    {"\xff\xfe", -32700},
    {"[]", -32600},
    {"42", -32600},
    {R"({"jsonrpc":"2.0","id":{"x":1},"method":"shutdown"})", -32600},
    {R"({"jsonrpc":"2.0","id":5,"method":7})", -32600},
    {R"({"jsonrpc":"1.0","id":5,"method":"shutdown"})", -32600},
    {R"({"jsonrpc":"2.0","id":5,"method":"initialize","params":"x"})", -32600},
    {R"({"jsonrpc":"2.0","id":5})", -32600},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/hover","params":[1]})", -32602},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/hover",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"},"position":{"line":"0"}}})",
     -32602},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/hover",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"},
                  "position":{"line":1e300,"character":0}}})",
     -32602},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/hover",
        "params":{"textDocument":{"uri":"file:///never/opened.ehl"},
                  "position":{"line":0,"character":0}}})",
     -32602},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/rename",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"},
                  "position":{"line":0,"character":5},"newName":7}})",
     -32602},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/noSuchFeature",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"}}})",
     -32601},
    {R"({"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":5}})", 0},
    {R"({"jsonrpc":"2.0","method":"textDocument/didOpen",
        "params":{"textDocument":{"uri":"file:///x.ehl","text":7}}})",
     0},
    {R"({"jsonrpc":"2.0","method":"textDocument/didChange",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"},
                  "contentChanges":[{"range":{"start":{"line":-1,"character":0},
                                              "end":{"line":0,"character":"x"}},"text":"a"}]}})",
     0},
    {R"({"jsonrpc":"2.0","method":"textDocument/didChange",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"},"contentChanges":{"text":"a"}}})",
     0},
    {R"({"jsonrpc":"2.0","method":"textDocument/didClose","params":null})", 0},
    {R"({"jsonrpc":"2.0","method":5})", 0},
    {R"({"jsonrpc":"2.0","id":9,"result":null})", 0},
    {R"({"jsonrpc":"2.0","id":9,"error":{"code":1,"message":"x"}})", 0},
    {R"({"jsonrpc":"2.0","method":"$/cancelRequest","params":{"id":[]}})", 0},
    {R"({"jsonrpc":"2.0","method":"workspace/didChangeWorkspaceFolders","params":{"event":5}})", 0},
    {R"({"jsonrpc":"2.0","method":"workspace/didChangeWorkspaceFolders",
        "params":{"event":{"added":[5],"removed":[]}}})",
     0},
    {R"({"jsonrpc":"2.0","method":"workspace/didChangeWorkspaceFolders",
        "params":{"event":{"added":[{"uri":5}],"removed":{"uri":"file:///w"}}}})",
     0},
    {R"({"jsonrpc":"2.0","id":5,"method":"textDocument/prepareRename",
        "params":{"textDocument":{"uri":"file:///w/ok.ehl"},"position":{"line":0}}})",
     -32602},
};

TEST(LspHostile, EveryHostileMessageIsAnsweredOrDroppedAndTheServerGoesOn) {
  LspClient c;
  c.initialize();
  const std::string good = "int done\nfunction main()\ndone = 1\nreturn\n";
  ASSERT_EQ(c.open("file:///w/ok.ehl", "gold", good)["diagnostics"], json::array());
  int n = 0;
  for (const Hostile& h : kHostile) {
    SCOPED_TRACE(h.text);
    const std::vector<json> out = c.raw(h.text);
    if (h.code == 0) {
      for (const json& m : out) EXPECT_FALSE(m.contains("id")) << m.dump();  // no answer
    } else {
      ASSERT_EQ(out.size(), 1u);
      EXPECT_EQ(out[0]["error"]["code"], h.code);
      const json sent = json::parse(h.text, nullptr, false);
      const bool id_usable = sent.is_object() && (sent.value("id", json()).is_number_integer());
      EXPECT_EQ(out[0]["id"], id_usable ? sent["id"] : json());
    }
    // Still serving: a new document is checked, the open one kept its text.
    const json p = c.open("file:///w/next" + std::to_string(n++) + ".ehl", "gold",
                          "function main()\nx = 1 +\nreturn\n");
    ASSERT_FALSE(p.is_null());
    EXPECT_EQ(p["diagnostics"].at(0)["code"], 7);  // Gold 7 "Value is expected"
  }
  // The hostile didChanges left ok.ehl as it was: a save checks it again, still clean.
  c.notify("textDocument/didSave", {{"textDocument", {{"uri", "file:///w/ok.ehl"}}}});
  bool checked = false;
  for (const json& m : c.wait(0)) {
    if (m["params"]["uri"] != "file:///w/ok.ehl") continue;
    checked = true;
    EXPECT_EQ(m["params"]["diagnostics"], json::array());
  }
  EXPECT_TRUE(checked);
}

TEST(LspHostile, AWrongParamsFieldIsInvalidParams) {
  // initialize's own capabilities of the wrong type, before initialize: -32602 to its id.
  LspClient fresh;
  const std::vector<json> out =
      fresh.raw(R"({"jsonrpc":"2.0","id":3,"method":"initialize","params":{"capabilities":[]}})");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["id"], 3);
  EXPECT_EQ(out[0]["error"]["code"], -32602);
  // And it may be sent again, well formed.
  EXPECT_TRUE(fresh.initialize().contains("result"));
}

TEST(LspHostile, WorkspaceFoldersThatAreNoFoldersAreSkipped) {
  // Folders that are not objects or name no file URI, a rootUri of the wrong type: initialize
  // still answers, and a document is checked.
  LspClient c;
  const std::vector<json> out = c.raw(
      R"({"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{},
          "rootUri":7,"workspaceFolders":[5,{"uri":5},{"uri":"http://x/"},{"name":"n"}]}})");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].contains("result")) << out[0].dump();
  c.notify("initialized");
  const json p = c.open("file:///w/ok.ehl", "gold", "function main()\nx = 1 +\nreturn\n");
  ASSERT_FALSE(p.is_null());
  EXPECT_EQ(p["diagnostics"].at(0)["code"], 7);  // Gold 7 "Value is expected"
}

}  // namespace
}  // namespace uprog::lsp
