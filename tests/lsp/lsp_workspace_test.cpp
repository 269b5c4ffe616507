// The features beyond one document: an #include found beside the document, then in each
// workspace folder (initialize's workspaceFolders or rootUri, didChangeWorkspaceFolders); an
// open header's unsaved text compiled in place of its file's; references and rename of a name a
// header declares, across the header and every open document that includes it; rename refusing
// the language's and the drive's words and names that are not names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lsp_client.h"

namespace uprog::lsp {
namespace {

namespace fs = std::filesystem;

// A fresh folder for one test, removed after it. Named after the test too: tests that share a
// fixture run side by side under `ctest -j`, and one's removal must not empty the other's folder.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             (name + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string uri(const std::string& file) const { return "file://" + (path / file).string(); }
  void write(const std::string& file, const std::string& text) const {
    fs::create_directories((path / file).parent_path());
    std::ofstream(path / file) << text;
  }
};

json folder(const TempDir& d, const std::string& sub) {
  return {{"uri", d.uri(sub)}, {"name", sub}};
}

void initialize_in(LspClient& c, json workspace) {
  json params = {{"processId", nullptr}, {"capabilities", json::object()}};
  params.update(workspace);
  const std::vector<json> out = c.request("initialize", params);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_TRUE(out[0].contains("result")) << out[0].dump();
  EXPECT_EQ(out[0]["result"]["capabilities"]["workspace"]["workspaceFolders"]["supported"], true);
  c.notify("initialized");
}

json at(const std::string& uri, int line, int character) {
  return {{"textDocument", {{"uri", uri}}},
          {"position", {{"line", line}, {"character", character}}}};
}

json range(int line, int from, int to) {
  return {{"start", {{"line", line}, {"character", from}}},
          {"end", {{"line", line}, {"character", to}}}};
}

// The manual's (HIWIN PDL 2.5.6) form: a procedure in a header, included by name.
const char kTwiceHeader[] = "#long shared\nproc twice(long x, long* out) do\n  *out=x*2;\nend;\n";
const char kTwiceUser[] = "#include \"twice.h\"\n#long v\n#task/1;\ntwice(v, &shared);\nhalt;\n";

TEST(LspWorkspace, PdlIncludeIsFoundInAWorkspaceFolder) {
  TempDir d("uprog_lsp_ws_pdl");
  d.write("lib/twice.h", kTwiceHeader);
  d.write("src/main.pdl", kTwiceUser);
  // Without the folder the header is nowhere: PDL 102 "cannot include the file" (errors.def).
  {
    LspClient c;
    initialize_in(c, {{"rootUri", nullptr}});
    const json p = c.open(d.uri("src/main.pdl"), "hiwin-pdl", kTwiceUser);
    ASSERT_FALSE(p["diagnostics"].empty()) << p.dump();
    EXPECT_EQ(p["diagnostics"][0]["code"], 102);
    EXPECT_EQ(p["diagnostics"][0]["range"]["start"]["line"], 0);
    // The folder added: the document is checked again, now clean.
    c.notify("workspace/didChangeWorkspaceFolders",
             {{"event", {{"added", {folder(d, "lib")}}, {"removed", json::array()}}}});
    const json again = published(c.wait(0));
    ASSERT_FALSE(again.is_null());
    EXPECT_EQ(again["diagnostics"], json::array()) << again.dump();
    // And removed again: not found again.
    c.notify("workspace/didChangeWorkspaceFolders",
             {{"event", {{"added", json::array()}, {"removed", {folder(d, "lib")}}}}});
    const json removed = published(c.wait(0));
    ASSERT_FALSE(removed.is_null());
    ASSERT_FALSE(removed["diagnostics"].empty());
    EXPECT_EQ(removed["diagnostics"][0]["code"], 102);
  }
  // Given at initialize: clean at once, and go to definition lands in the folder's header.
  LspClient c;
  initialize_in(c, {{"workspaceFolders", {folder(d, "src"), folder(d, "lib")}}});
  const json p = c.open(d.uri("src/main.pdl"), "hiwin-pdl", kTwiceUser);
  EXPECT_EQ(p["diagnostics"], json::array()) << p.dump();
  const std::vector<json> out =
      c.request("textDocument/definition", at(d.uri("src/main.pdl"), 3, 1));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["result"]["uri"], d.uri("lib/twice.h"));
  EXPECT_EQ(out[0]["result"]["range"], range(1, 5, 10));  // "twice" in "proc twice(...)"
}

TEST(LspWorkspace, PupHeaderIsFoundInTheRootFolder) {
  // examples/pup/library_user.pup and its axis_library.puh, the header in the workspace's root
  // and the program in a folder of its own.
  TempDir d("uprog_lsp_ws_pup");
  const fs::path examples = fs::path(UPROG_SOURCE_DIR) / "examples" / "pup";
  fs::copy_file(examples / "axis_library.puh", d.path / "axis_library.puh");
  std::ifstream in(examples / "library_user.pup");
  const std::string program((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  d.write("app/library_user.pup", program);
  LspClient c;
  initialize_in(c, {{"rootUri", "file://" + d.path.string()}});
  const std::string uri = d.uri("app/library_user.pup");
  const json p = c.open(uri, "akribis-pup", program);
  EXPECT_EQ(p["diagnostics"], json::array()) << p.dump();
  // Target (the program's line 9, "Target = 5000") is the header's #definevar on its line 6.
  const std::vector<json> def = c.request("textDocument/definition", at(uri, 8, 2));
  ASSERT_EQ(def.size(), 1u);
  EXPECT_EQ(def[0]["result"]["uri"], d.uri("axis_library.puh"));
  EXPECT_EQ(def[0]["result"]["range"]["start"]["line"], 5);
  // Hover names the header, completion offers its names.
  const std::vector<json> hover = c.request("textDocument/hover", at(uri, 8, 2));
  ASSERT_EQ(hover.size(), 1u);
  const std::string text = hover[0]["result"]["contents"]["value"];
  EXPECT_NE(text.find("axis_library.puh"), std::string::npos) << text;
  const std::vector<json> done = c.request("textDocument/completion", at(uri, 7, 0));
  bool offers_moves = false;
  for (const json& item : done[0]["result"]["items"]) offers_moves |= item["label"] == "Moves";
  EXPECT_TRUE(offers_moves);
  // Its semantic token is the header's variable's: (line, character, length, type) decoded from
  // LSP's relative encoding; type 2 is "variable" in the legend.
  const std::vector<json> tokens =
      c.request("textDocument/semanticTokens/full", {{"textDocument", {{"uri", uri}}}});
  const json& data = tokens.at(0)["result"]["data"];
  int64_t line = 0, character = 0;
  bool target_is_variable = false;
  for (size_t i = 0; i + 4 < data.size(); i += 5) {
    line += data[i].get<int64_t>();
    character = data[i].get<int64_t>() == 0 ? character + data[i + 1].get<int64_t>()
                                            : data[i + 1].get<int64_t>();
    if (line == 8 && character == 0)
      target_is_variable = data[i + 2] == 6 && data[i + 3] == 2;  // "Target", variable
  }
  EXPECT_TRUE(target_is_variable) << data.dump();
}

TEST(LspWorkspace, AnOpenHeadersUnsavedTextIsCompiled) {
  TempDir d("uprog_lsp_ws_unsaved");
  d.write("twice.h", kTwiceHeader);
  LspClient c;
  initialize_in(c, {{"rootUri", "file://" + d.path.string()}});
  const json p = c.open(d.uri("main.pdl"), "hiwin-pdl", kTwiceUser);
  EXPECT_EQ(p["diagnostics"], json::array()) << p.dump();
  // The header opened and edited, not saved: "*out=x*y;" names what is not declared, PDL 20
  // "unknown name" (errors.def) at `y` (its line 3, column 10), shown on main.pdl's #include line.
  const std::string header_uri = d.uri("twice.h");
  c.open(header_uri, "hiwin-pdl", kTwiceHeader);
  c.notify("textDocument/didChange",
           {{"textDocument", {{"uri", header_uri}, {"version", 2}}},
            {"contentChanges",
             {{{"text", "#long shared\nproc twice(long x, long* out) do\n  *out=x*y;\nend;\n"}}}}});
  json main_diagnostics;
  for (const json& m : c.wait(1000)) {
    if (m.value("method", "") == "textDocument/publishDiagnostics" &&
        m["params"]["uri"] == d.uri("main.pdl"))
      main_diagnostics = m["params"]["diagnostics"];
  }
  ASSERT_EQ(main_diagnostics.size(), 1u) << main_diagnostics.dump();
  const json& diag = main_diagnostics[0];
  EXPECT_EQ(diag["code"], 20);
  EXPECT_EQ(diag["range"]["start"]["line"], 0);  // #include "twice.h"
  ASSERT_EQ(diag["relatedInformation"].size(), 1u);
  EXPECT_EQ(diag["relatedInformation"][0]["location"]["uri"], header_uri);
  EXPECT_EQ(diag["relatedInformation"][0]["location"]["range"], range(2, 9, 10));
  // Closed unsaved: the file on disk counts again.
  c.notify("textDocument/didClose", {{"textDocument", {{"uri", header_uri}}}});
  json after_close;
  for (const json& m : c.wait(0)) {
    if (m.value("method", "") == "textDocument/publishDiagnostics" &&
        m["params"]["uri"] == d.uri("main.pdl"))
      after_close = m["params"]["diagnostics"];
  }
  EXPECT_EQ(after_close, json::array());
}

// The publishDiagnostics params for `uri` among `messages` (null when none came).
json published_for(const std::vector<json>& messages, const std::string& uri) {
  json found;
  for (const json& m : messages)
    if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri)
      found = m["params"];
  return found;
}

TEST(LspWorkspace, AnErrorInAClosedHeaderIsShownInTheHeaderToo) {
  TempDir d("uprog_lsp_ws_header_diagnostics");
  // PDL 20 "unknown name" at `y`, twice.h's line 3, column 10.
  d.write("twice.h", "#long shared\nproc twice(long x, long* out) do\n  *out=x*y;\nend;\n");
  LspClient c;
  initialize_in(c, {{"rootUri", "file://" + d.path.string()}});
  const std::vector<json> opened = c.notify("textDocument/didOpen", {{"textDocument",
                                                                      {{"uri", d.uri("main.pdl")},
                                                                       {"languageId", "hiwin-pdl"},
                                                                       {"version", 1},
                                                                       {"text", kTwiceUser}}}});
  const json header = published_for(opened, d.uri("twice.h"));
  ASSERT_FALSE(header.is_null());
  ASSERT_EQ(header["diagnostics"].size(), 1u) << header.dump();
  const json& diag = header["diagnostics"][0];
  EXPECT_EQ(diag["code"], 20);
  EXPECT_EQ(diag["range"], range(2, 9, 10));
  EXPECT_EQ(diag["relatedInformation"][0]["location"]["uri"], d.uri("main.pdl"));
  EXPECT_EQ(diag["relatedInformation"][0]["location"]["range"]["start"]["line"], 0);
  // Fixed on disk: the header's diagnostics are cleared.
  d.write("twice.h", kTwiceHeader);
  c.notify("workspace/didChangeWatchedFiles",
           {{"changes", {{{"uri", d.uri("twice.h")}, {"type", 2}}}}});
  const json cleared = published_for(c.wait(0), d.uri("twice.h"));
  ASSERT_FALSE(cleared.is_null());
  EXPECT_EQ(cleared["diagnostics"], json::array());
}

// twice.h and two open documents that include it, one of them also naming `shared`.
struct TwoIncluders {
  TempDir d{"uprog_lsp_ws_rename"};
  LspClient c;
  std::string header, first, second;
  TwoIncluders() {
    d.write("twice.h", kTwiceHeader);
    header = d.uri("twice.h");
    first = d.uri("a.pdl");
    second = d.uri("b.pdl");
    c.initialize();
    c.open(first, "hiwin-pdl", kTwiceUser);
    c.open(second, "hiwin-pdl", "#include \"twice.h\"\n#task/1;\ntwice(1, &shared);\nhalt;\n");
  }
};

TEST(LspWorkspace, ReferencesOfAHeadersNameReachEveryIncluder) {
  TwoIncluders w;
  // On `twice` in a.pdl (line 3): the header's declaration, a.pdl's call and b.pdl's.
  std::vector<json> out = w.c.request("textDocument/references", at(w.first, 3, 2));
  ASSERT_EQ(out.size(), 1u);
  const json expected = json::array({{{"uri", w.header}, {"range", range(1, 5, 10)}},
                                     {{"uri", w.first}, {"range", range(3, 0, 5)}},
                                     {{"uri", w.second}, {"range", range(2, 0, 5)}}});
  EXPECT_EQ(out[0]["result"], expected) << out[0]["result"].dump();
  // Without the declaration; asked from b.pdl's use of `shared` (line 2, "twice(1, &shared)").
  json params = at(w.second, 2, 11);
  params["context"] = {{"includeDeclaration", false}};
  out = w.c.request("textDocument/references", params);
  // The file it is declared in first, then the one asked from, then the other includers.
  const json uses = json::array({{{"uri", w.second}, {"range", range(2, 10, 16)}},
                                 {{"uri", w.first}, {"range", range(3, 10, 16)}}});
  EXPECT_EQ(out[0]["result"], uses) << out[0]["result"].dump();
  // Asked from the header itself, open in the editor: the same places.
  w.c.open(w.header, "hiwin-pdl", kTwiceHeader);
  out = w.c.request("textDocument/references", at(w.header, 1, 6));
  EXPECT_EQ(out[0]["result"], expected) << out[0]["result"].dump();
}

TEST(LspWorkspace, RenameOfAHeadersNameEditsEveryFile) {
  TwoIncluders w;
  const std::vector<json> out = w.c.request("textDocument/rename", [&] {
    json p = at(w.second, 2, 0);
    p["newName"] = "double_it";
    return p;
  }());
  ASSERT_EQ(out.size(), 1u);
  const json& changes = out[0]["result"]["changes"];
  ASSERT_EQ(changes.size(), 3u) << changes.dump();
  EXPECT_EQ(changes[w.header],
            json::array({{{"range", range(1, 5, 10)}, {"newText", "double_it"}}}));
  EXPECT_EQ(changes[w.first], json::array({{{"range", range(3, 0, 5)}, {"newText", "double_it"}}}));
  EXPECT_EQ(changes[w.second],
            json::array({{{"range", range(2, 0, 5)}, {"newText", "double_it"}}}));
}

// A refused rename: RequestFailed (LSP 3.17, -32803) with a message that says why.
void expect_refused(LspClient& c, json params, const std::string& new_name,
                    const std::string& says) {
  params["newName"] = new_name;
  const std::vector<json> out = c.request("textDocument/rename", params);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_TRUE(out[0].contains("error")) << out[0].dump();
  EXPECT_EQ(out[0]["error"]["code"], -32803);
  const std::string message = out[0]["error"]["message"];
  EXPECT_NE(message.find(says), std::string::npos) << message;
}

TEST(LspWorkspace, RenameRefusesWordsOfTheLanguageAndBadNames) {
  TwoIncluders w;
  // The program's name to a keyword (PDL's `while`), a built-in (`max`), a non-name, a name
  // already declared beside it.
  expect_refused(w.c, at(w.first, 1, 6), "while", "keyword");
  expect_refused(w.c, at(w.first, 1, 6), "max", "function");
  expect_refused(w.c, at(w.first, 1, 6), "2fast", "not a name");
  expect_refused(w.c, at(w.first, 1, 6), "", "not a name");
  expect_refused(w.c, at(w.first, 1, 6), "shared", "already declared");
  // A word of the language or the drive is not the program's to rename.
  expect_refused(w.c, at(w.first, 4, 1), "stop", "not a name of the program's");  // halt
  // prepareRename (LSP 3.17) answers the same before the user types a new name.
  std::vector<json> out = w.c.request("textDocument/prepareRename", at(w.first, 3, 2));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["result"], (json{{"range", range(3, 0, 5)}, {"placeholder", "twice"}}));
  out = w.c.request("textDocument/prepareRename", at(w.first, 4, 1));
  EXPECT_EQ(out.at(0)["error"]["code"], -32803) << out.at(0).dump();
  LspClient g;
  g.initialize();
  const std::string gold = "file:///w/r.ehl";
  g.open(gold, "elmo-gold", "int k\nfunction main()\nMO = 1\nk = sin(0.5)\nreturn\n");
  expect_refused(g, at(gold, 2, 0), "motor", "drive command");
  expect_refused(g, at(gold, 3, 5), "sine", "not a name of the program's");
}

}  // namespace
}  // namespace uprog::lsp
