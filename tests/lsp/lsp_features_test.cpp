// The editor features on one program per dialect, driven as an editor drives them: hover over a
// drive command (its reference entry's text and source), completion, go to a function, find
// references, rename, signature help, the outline, folding and semantic tokens. Each program
// compiles clean; the expected places are where the program text has the names.
#include <gtest/gtest.h>

#include "lsp_client.h"

namespace uprog::lsp {
namespace {

struct At {
  int line, character;  // 0-based, as LSP counts
};

struct FeatureCase {
  std::string dialect, language_id, uri, text;
  At command;                          // on a drive command or system variable
  std::string command_name;            // its reference entry
  At call;                             // on a call of the user's function
  At function;                         // where that function's name is declared
  At global;                           // on a use of a global variable
  size_t global_uses;                  // every word that names it, the declaration too
  At builtin_argument;                 // inside a built-in's argument list, or {-1, -1}
  std::string builtin_label;           // that built-in's signature
  std::vector<std::string> outline;    // the outline's top-level names
  std::vector<std::string> completes;  // what completion offers at the start of line `call`
};

void PrintTo(const FeatureCase& k, std::ostream* os) { *os << k.dialect; }

std::string line_of(const std::string& text, int n) {
  size_t at = 0;
  for (int i = 0; i < n; ++i) at = text.find('\n', at) + 1;
  return text.substr(at, text.find('\n', at) - at);
}

const FeatureCase kCases[] = {
    {"gold",
     "elmo-gold",
     "file:///w/features.ehl",
     "int total\nfunction main()\nint k\ntotal = 0\nMO = 1\nk = sin(0.5)\nhelper()\nreturn\n\n"
     "function helper()\ntotal = total + 1\nreturn\n",
     {4, 0},
     "MO",
     {6, 2},
     {9, 9},
     {3, 1},
     4,
     {5, 9},
     "sin(x)",
     {"total", "main", "helper"},
     {"total", "k", "helper", "MO", "while", "sin"}},
    {"pdl",
     "hiwin-pdl",
     "file:///w/features.pdl",
     "#long total\nproc add(long k) do\n  total=total+k;\nend;\n#task/1;\nseton X_enable;\n"
     "X_vel_max=max(total, 20000);\nadd(5);\nhalt;\n",
     {6, 3},
     "X_vel_max",
     {7, 1},
     {1, 5},
     {2, 3},
     4,
     {6, 17},
     "max(a, b)",
     {"total", "add", "task 1"},
     {"total", "add", "X_vel_max", "seton", "while", "max"}},
    {"pup",
     "akribis-pup",
     "file:///w/features.pup",
     "#definevar Count AGenData[1]\n#define ADD_ONE 1\nAProgTask[1]\nAMotorOn = 1\nCount = 0\n"
     "AProgFuncCall, ADD_ONE\nAProgHalt[1]\nAProgFunc[ADD_ONE]\nCount = power(Count, 1) + 1\n"
     "return\n",
     {3, 2},
     "AMotorOn",
     {5, 17},
     {7, 10},
     {4, 1},
     4,
     {8, 15},
     "power(a, b)",
     {"Count", "ADD_ONE", "task 1", "ADD_ONE"},
     {"Count", "ADD_ONE", "AMotorOn", "while", "sqrt"}},
    {"st",
     "kollmorgen-st",
     "file:///w/features.st",
     "LONG TOTAL, SPEED;\n\nFUNCTION BUMP\n  TOTAL := TOTAL + 1;\nEND_FUNCTION\n\n"
     "PROGRAM PLCMAIN\n  XREAD('VLIM', SPEED);\n  FUNCTION (BUMP);\nEND_PROGRAM\n",
     {7, 10},
     "VLIM",
     {8, 13},
     {2, 9},
     {3, 4},
     3,
     {7, 16},
     "XREAD('NAME', V)",
     {"TOTAL", "SPEED", "BUMP", "PLCMAIN"},
     {"TOTAL", "SPEED", "BUMP", "XREAD", "IF", "VLIM"}},
};

json at(const FeatureCase& k, At p) {
  return {{"textDocument", {{"uri", k.uri}}},
          {"position", {{"line", p.line}, {"character", p.character}}}};
}

class LspFeatures : public ::testing::TestWithParam<FeatureCase> {
 protected:
  LspClient c;
  void SetUp() override {
    const FeatureCase& k = GetParam();
    c.initialize({{"textDocument",
                   {{"completion", {{"completionItem", {{"snippetSupport", true}}}}},
                    {"documentSymbol", {{"hierarchicalDocumentSymbolSupport", true}}}}}});
    const json p = c.open(k.uri, k.language_id, k.text);
    ASSERT_EQ(p["diagnostics"], json::array()) << p.dump();  // the program compiles clean
  }
  json result(const std::string& method, json params) {
    const std::vector<json> out = c.request(method, std::move(params));
    EXPECT_EQ(out.size(), 1u);
    EXPECT_FALSE(out.at(0).contains("error")) << out.at(0).dump();
    return out.at(0)["result"];
  }
};

TEST_P(LspFeatures, HoverOverADriveCommandShowsItsReferenceEntry) {
  const FeatureCase& k = GetParam();
  const json h = result("textDocument/hover", at(k, k.command));
  ASSERT_TRUE(h.is_object()) << h.dump();
  const std::string text = h["contents"]["value"];
  const dialect::ReferenceEntry* entry = nullptr;
  const std::vector<dialect::ReferenceEntry> all = dialects::find(k.dialect)->reference();
  for (const dialect::ReferenceEntry& e : all)
    if (e.name == k.command_name) entry = &e;
  ASSERT_NE(entry, nullptr);
  EXPECT_NE(text.find(entry->summary), std::string::npos) << text;
  EXPECT_NE(text.find(entry->source), std::string::npos) << text;
  EXPECT_EQ(h["range"]["start"]["line"], k.command.line);
}

TEST_P(LspFeatures, GoToTheFunction) {
  const FeatureCase& k = GetParam();
  const json d = result("textDocument/definition", at(k, k.call));
  ASSERT_TRUE(d.is_object()) << d.dump();
  EXPECT_EQ(d["uri"], k.uri);
  EXPECT_EQ(d["range"]["start"],
            (json{{"line", k.function.line}, {"character", k.function.character}}));
}

// The name around character `at` of `line`.
std::string name_around(const std::string& line, int at) {
  const auto name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  size_t b = static_cast<size_t>(at), e = static_cast<size_t>(at);
  while (b > 0 && name_char(line[b - 1])) --b;
  while (e < line.size() && name_char(line[e])) ++e;
  return line.substr(b, e - b);
}

TEST_P(LspFeatures, ReferencesAndRenameOfAGlobal) {
  const FeatureCase& k = GetParam();
  const std::string old_name = name_around(line_of(k.text, k.global.line), k.global.character);
  json params = at(k, k.global);
  params["context"] = {{"includeDeclaration", true}};
  json refs = result("textDocument/references", params);
  EXPECT_EQ(refs.size(), k.global_uses) << refs.dump();
  params["context"] = {{"includeDeclaration", false}};
  refs = result("textDocument/references", params);
  EXPECT_EQ(refs.size(), k.global_uses - 1) << refs.dump();
  params = at(k, k.global);
  params["newName"] = "RENAMED";
  const json edit = result("textDocument/rename", params);
  const json& edits = edit["changes"][k.uri];
  ASSERT_EQ(edits.size(), k.global_uses);
  for (const json& e : edits) {
    EXPECT_EQ(e["newText"], "RENAMED");
    const std::string line = line_of(k.text, e["range"]["start"]["line"]);
    const int from = e["range"]["start"]["character"], to = e["range"]["end"]["character"];
    EXPECT_EQ(line.substr(static_cast<size_t>(from), static_cast<size_t>(to - from)), old_name);
  }
  // A drive command is not the document's to rename.
  params = at(k, k.command);
  params["newName"] = "RENAMED";
  const std::vector<json> out = c.request("textDocument/rename", params);
  EXPECT_EQ(out.at(0)["error"]["code"], -32803);
}

TEST_P(LspFeatures, CompletionOffersTheWordsInScope) {
  const FeatureCase& k = GetParam();
  const json list = result("textDocument/completion", at(k, {k.call.line, 0}));
  std::vector<std::string> labels;
  for (const json& item : list["items"]) labels.push_back(item["label"]);
  for (const std::string& want : k.completes)
    EXPECT_NE(std::find(labels.begin(), labels.end(), want), labels.end()) << want;
  // A built-in comes with its arguments as a snippet.
  for (const json& item : list["items"]) {
    if (item["label"] != k.builtin_label.substr(0, k.builtin_label.find('('))) continue;
    EXPECT_EQ(item["insertTextFormat"], 2);
    EXPECT_EQ(item["insertText"].get<std::string>().find(
                  k.builtin_label.substr(0, k.builtin_label.find('(') + 1) + "${1:"),
              0u);
  }
}

TEST_P(LspFeatures, SignatureHelpOfABuiltin) {
  const FeatureCase& k = GetParam();
  const json s = result("textDocument/signatureHelp", at(k, k.builtin_argument));
  ASSERT_TRUE(s.is_object()) << s.dump();
  EXPECT_EQ(s["signatures"][0]["label"], k.builtin_label);
}

TEST_P(LspFeatures, OutlineFoldingAndSemanticTokens) {
  const FeatureCase& k = GetParam();
  const json symbols = result("textDocument/documentSymbol", {{"textDocument", {{"uri", k.uri}}}});
  std::vector<std::string> names;
  for (const json& s : symbols) names.push_back(s["name"]);
  EXPECT_EQ(names, k.outline);
  const json folds = result("textDocument/foldingRange", {{"textDocument", {{"uri", k.uri}}}});
  EXPECT_FALSE(folds.empty());
  for (const json& f : folds) EXPECT_LT(f["startLine"].get<int>(), f["endLine"].get<int>());
  const json tokens =
      result("textDocument/semanticTokens/full", {{"textDocument", {{"uri", k.uri}}}});
  ASSERT_EQ(tokens["data"].size() % 5, 0u);
  EXPECT_GE(tokens["data"].size(), 5u * 4);
}

INSTANTIATE_TEST_SUITE_P(EveryDialect, LspFeatures, ::testing::ValuesIn(kCases),
                         [](const auto& c) { return c.param.dialect; });

}  // namespace
}  // namespace uprog::lsp
