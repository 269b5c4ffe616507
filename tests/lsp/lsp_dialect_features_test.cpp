// The feature list once per dialect, on a program in that dialect's own syntax (the
// manual's forms named beside each): hover over the user's names (their declaration and type),
// completion of the locals in scope, labels and #define'd names, built-ins as snippets,
// signature help inside nested calls, folding ranges and the outline of routines, labels and
// tasks. Every expected place is where the program's text has the name.
#include <gtest/gtest.h>

#include <map>

#include "lsp_client.h"

namespace uprog::lsp {
namespace {

class Session {
 public:
  Session(std::string uri, const std::string& language_id, const std::string& text)
      : uri_(std::move(uri)) {
    c_.initialize({{"textDocument",
                    {{"completion", {{"completionItem", {{"snippetSupport", true}}}}},
                     {"documentSymbol", {{"hierarchicalDocumentSymbolSupport", true}}}}}});
    diagnostics_ = c_.open(uri_, language_id, text)["diagnostics"];
  }
  const json& diagnostics() const { return diagnostics_; }
  // The whole text replaced, as a client without incremental sync sends it.
  void change(const std::string& text) {
    c_.notify("textDocument/didChange", {{"textDocument", {{"uri", uri_}, {"version", ++version_}}},
                                         {"contentChanges", {{{"text", text}}}}});
  }
  json result(const std::string& method, int line = -1, int character = -1) {
    json params = {{"textDocument", {{"uri", uri_}}}};
    if (line >= 0) params["position"] = {{"line", line}, {"character", character}};
    const std::vector<json> out = c_.request(method, params);
    EXPECT_EQ(out.size(), 1u);
    EXPECT_FALSE(out.at(0).contains("error")) << out.at(0).dump();
    return out.at(0)["result"];
  }
  std::string hover(int line, int character) {
    const json h = result("textDocument/hover", line, character);
    return h.is_object() ? h["contents"]["value"].get<std::string>() : "";
  }
  // The completion items at the place, by label.
  std::map<std::string, json> completion(int line, int character) {
    std::map<std::string, json> items;
    const json list = result("textDocument/completion", line, character);
    for (const json& item : list["items"]) items[item["label"].get<std::string>()] = item;
    return items;
  }
  // The signature label and active parameter at the place; "" when none.
  std::pair<std::string, int> signature(int line, int character) {
    const json s = result("textDocument/signatureHelp", line, character);
    if (!s.is_object()) return {"", -1};
    return {s["signatures"][0]["label"], s["activeParameter"]};
  }
  std::pair<int, int> definition(int line, int character) {
    const json d = result("textDocument/definition", line, character);
    if (!d.is_object()) return {-1, -1};
    EXPECT_EQ(d["uri"], uri_);
    return {d["range"]["start"]["line"], d["range"]["start"]["character"]};
  }
  std::vector<std::pair<int, int>> references(int line, int character) {
    std::vector<std::pair<int, int>> out;
    for (const json& r : result("textDocument/references", line, character))
      out.emplace_back(r["range"]["start"]["line"], r["range"]["start"]["character"]);
    return out;
  }
  std::vector<std::pair<int, int>> folds() {
    std::vector<std::pair<int, int>> out;
    for (const json& f : result("textDocument/foldingRange"))
      out.emplace_back(f["startLine"], f["endLine"]);
    return out;
  }
  // The outline: "name" per top-level symbol, "name(child child)" where it has children.
  std::vector<std::string> outline() {
    std::vector<std::string> out;
    for (const json& s : result("textDocument/documentSymbol")) {
      std::string entry = s["name"];
      if (s.contains("children")) {
        entry += "(";
        for (const json& c : s["children"]) entry += c["name"].get<std::string>() + " ";
        entry.back() = ')';
      }
      out.push_back(entry);
    }
    return out;
  }

 private:
  LspClient c_;
  std::string uri_;
  json diagnostics_;
  int version_ = 1;
};

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

using Places = std::vector<std::pair<int, int>>;
using Names = std::vector<std::string>;

// Gold: #define (manual 2.9.1), a global label and a local one with goto ##LABEL (2.11.2), a
// function with a local and one with an output and an input (2.5), nested built-ins (1.12).
const char kGold[] =
    "// features\n"                          // 0
    "#define LIMIT 1000\n"                   // 1
    "int count\n"                            // 2
    "##START\n"                              // 3
    "count = 0\n"                            // 4
    "main()\n"                               // 5
    "\n"                                     // 6
    "function main()\n"                      // 7
    "int k\n"                                // 8
    "k = LIMIT\n"                            // 9
    "##AGAIN\n"                              // 10
    "count = count + 1\n"                    // 11
    "if (count < 3)\n"                       // 12
    "  goto ##AGAIN\n"                       // 13
    "end\n"                                  // 14
    "k = fix((abs(k - 1) + sqrt(4)) / 2)\n"  // 15
    "return\n"                               // 16
    "\n"                                     // 17
    "function [float y] = half(float x)\n"   // 18
    "y = x / 2\n"                            // 19
    "return\n";                              // 20

TEST(LspDialectFeatures, Gold) {
  Session s("file:///w/features.ehl", "elmo-gold", kGold);
  ASSERT_EQ(s.diagnostics(), json::array()) << s.diagnostics().dump();
  EXPECT_EQ(s.outline(), (Names{"LIMIT", "count", "START", "main(k AGAIN)", "half(y x)"}));
  // A function's body ends at its `return` (manual 2.5).
  EXPECT_EQ(s.folds(), (Places{{7, 16}, {18, 20}}));
  const std::string k = s.hover(15, 0);
  EXPECT_TRUE(has(k, "int") && has(k, "variable of main") && has(k, "declared on line 9")) << k;
  const std::string x = s.hover(19, 4);
  EXPECT_TRUE(has(x, "float (input)") && has(x, "parameter of half")) << x;
  EXPECT_TRUE(has(s.hover(9, 5), "#define LIMIT 1000")) << s.hover(9, 5);
  // In main: its local and label, the globals, the macro; not half's names.
  std::map<std::string, json> items = s.completion(11, 0);
  for (const char* name : {"k", "AGAIN", "count", "LIMIT", "START", "main", "half"})
    EXPECT_TRUE(items.count(name)) << name;
  EXPECT_FALSE(items.count("x"));
  EXPECT_EQ(items["sqrt"]["insertText"], "sqrt(${1:x})");  // manual 1.12's sqrt(x)
  items = s.completion(19, 0);
  EXPECT_TRUE(items.count("x") && items.count("y"));
  EXPECT_FALSE(items.count("k"));
  EXPECT_EQ(s.definition(13, 10), (std::pair<int, int>{10, 2}));  // ##AGAIN's name
  EXPECT_EQ(s.references(1, 9), (Places{{1, 8}, {9, 4}}));
  // "k = fix((abs(k - 1) + sqrt(4)) / 2)": in abs; in the group after abs closed, fix's; in
  // sqrt; after the group, fix's again.
  EXPECT_EQ(s.signature(15, 14), (std::pair<std::string, int>{"abs(x)", 0}));
  EXPECT_EQ(s.signature(15, 21), (std::pair<std::string, int>{"fix(x)", 0}));
  EXPECT_EQ(s.signature(15, 27), (std::pair<std::string, int>{"sqrt(x)", 0}));
  EXPECT_EQ(s.signature(15, 33), (std::pair<std::string, int>{"fix(x)", 0}));
}

// Gold's declarations come from its compiler's front end when the source parses: an array's
// dimension (manual 2.6: `float speeds[4]`) is in its type, and a declaration a #define writes
// (2.9.1: the identifier is replaced by its string) is found where the macro stands. While the
// source does not parse, the word scanner's outline stands in (docs/editors.md).
TEST(LspDialectFeatures, GoldDeclarationsFromTheCompiler) {
  const std::string text =
      "#define DECLARE_LIMIT int limit\n"  // 0
      "float speeds[4]\n"                  // 1
      "DECLARE_LIMIT\n"                    // 2
      "function main()\n"                  // 3
      "limit = 3\n"                        // 4
      "speeds[1] = limit\n"                // 5
      "return\n";                          // 6
  Session s("file:///w/compiled.ehl", "elmo-gold", text);
  ASSERT_EQ(s.diagnostics(), json::array()) << s.diagnostics().dump();
  EXPECT_TRUE(has(s.hover(5, 1), "float[4] (global)")) << s.hover(5, 1);
  EXPECT_EQ(s.outline(), (Names{"DECLARE_LIMIT", "speeds", "limit", "main"}));
  EXPECT_EQ(s.definition(4, 1), (std::pair<int, int>{2, 0}));  // where the macro declares it
  // The server keeps the declarations per text: a change makes them again.
  s.change(text + "\nfunction more()\nreturn\n");
  EXPECT_EQ(s.outline(), (Names{"DECLARE_LIMIT", "speeds", "limit", "main", "more"}));
  // A syntax error (Gold 7, "x = 1 +"): the scanner's outline, the same names.
  Session broken("file:///w/broken.ehl", "elmo-gold",
                 "int count\nfunction main()\nint k\nk = 1 +\nreturn\n");
  ASSERT_FALSE(broken.diagnostics().empty());
  EXPECT_EQ(broken.outline(), (Names{"count", "main(k)"}));
}

// PDL: manual 2.5.1's add3 with its temporary (`#long tmp;` inside the procedure), 2.2.3's goto
// and label, #define (2.5.3), a built-in (2.3.1; PDL calls nest in no expression: a call is the
// whole right side, its arguments variables, the last may be a constant, 2.1).
const char kPdl[] =
    "// features\n"                                       // 0
    "#define LIMIT 20000\n"                               // 1
    "#long total\n"                                       // 2
    "proc add3(long a, long b, long c, long * sum) do\n"  // 3
    "    #long tmp;\n"                                    // 4
    "    tmp=a+b;\n"                                      // 5
    "    *sum=tmp+c;\n"                                   // 6
    "end;\n"                                              // 7
    "#task/1;\n"                                          // 8
    "again:\n"                                            // 9
    "add3(4, 5, 6, &total);\n"                            // 10
    "X_vel_max=min(total, LIMIT);\n"                      // 11
    "if (total<15) do\n"                                  // 12
    "  goto again;\n"                                     // 13
    "end;\n"                                              // 14
    "halt;\n";                                            // 15

TEST(LspDialectFeatures, Pdl) {
  Session s("file:///w/features.pdl", "hiwin-pdl", kPdl);
  ASSERT_EQ(s.diagnostics(), json::array()) << s.diagnostics().dump();
  EXPECT_EQ(s.outline(), (Names{"LIMIT", "total", "add3(a b c sum tmp)", "task 1", "again"}));
  EXPECT_EQ(s.folds(), (Places{{3, 7}, {8, 15}}));
  const std::string tmp = s.hover(5, 4);
  EXPECT_TRUE(has(tmp, "long (temporary)") && has(tmp, "of add3") && has(tmp, "line 5")) << tmp;
  EXPECT_TRUE(has(s.hover(6, 5), "long*")) << s.hover(6, 5);
  EXPECT_TRUE(has(s.hover(2, 7), "long (global)")) << s.hover(2, 7);
  std::map<std::string, json> items = s.completion(6, 0);
  for (const char* name : {"tmp", "a", "sum", "total", "LIMIT", "add3"})
    EXPECT_TRUE(items.count(name)) << name;
  items = s.completion(10, 0);
  EXPECT_FALSE(items.count("tmp"));
  EXPECT_TRUE(items.count("again"));
  EXPECT_EQ(items["min"]["insertText"], "min(${1:a}, ${2:b})");  // manual 2.3.1's min(a, b)
  EXPECT_EQ(s.definition(13, 8), (std::pair<int, int>{9, 0}));
  EXPECT_EQ(s.references(1, 9), (Places{{1, 8}, {11, 21}}));
  EXPECT_EQ(s.signature(11, 15), (std::pair<std::string, int>{"min(a, b)", 0}));
  EXPECT_EQ(s.signature(11, 21), (std::pair<std::string, int>{"min(a, b)", 1}));
  EXPECT_EQ(s.signature(10, 8),
            (std::pair<std::string, int>{"add3(long a, long b, long c, long * sum)", 1}));
}

// ST (docs/dialects/st.md): #DEFINE, a label `NAME:` at a line start and GOTO, a FUNCTION called
// as FUNCTION (NAME), a built-in (a statement whose arguments are variables: calls do not nest).
const char kSt[] =
    "// features\n"                  // 0
    "#DEFINE LIMIT 5000\n"           // 1
    "LONG STEP, SPEED, TOP;\n"       // 2
    "\n"                             // 3
    "FUNCTION CLAMP\n"               // 4
    "  LIMITW(SPEED, STEP, TOP);\n"  // 5
    "END_FUNCTION\n"                 // 6
    "\n"                             // 7
    "PROGRAM PLCMAIN\n"              // 8
    "AGAIN:\n"                       // 9
    "  XREAD('VLIM', SPEED);\n"      // 10
    "  FUNCTION (CLAMP);\n"          // 11
    "  IF SPEED < LIMIT THEN\n"      // 12
    "    GOTO AGAIN;\n"              // 13
    "  END_IF;\n"                    // 14
    "END_PROGRAM\n";                 // 15

TEST(LspDialectFeatures, St) {
  Session s("file:///w/features.st", "kollmorgen-st", kSt);
  ASSERT_EQ(s.diagnostics(), json::array()) << s.diagnostics().dump();
  EXPECT_EQ(s.outline(), (Names{"LIMIT", "STEP", "SPEED", "TOP", "CLAMP", "PLCMAIN(AGAIN)"}));
  EXPECT_EQ(s.folds(), (Places{{4, 6}, {8, 15}}));
  const std::string step = s.hover(5, 17);
  EXPECT_TRUE(has(step, "LONG") && has(step, "declared on line 3")) << step;
  EXPECT_TRUE(has(s.hover(11, 14), "FUNCTION")) << s.hover(11, 14);
  std::map<std::string, json> items = s.completion(10, 0);
  for (const char* name : {"AGAIN", "LIMIT", "CLAMP", "STEP", "SPEED"})
    EXPECT_TRUE(items.count(name)) << name;
  EXPECT_EQ(items["XREAD"]["insertText"], "XREAD(${1:'NAME'}, ${2:V})");
  EXPECT_FALSE(s.completion(5, 0).count("AGAIN"));  // PLCMAIN's label
  EXPECT_EQ(s.definition(13, 10), (std::pair<int, int>{9, 0}));
  EXPECT_EQ(s.definition(11, 14), (std::pair<int, int>{4, 9}));
  EXPECT_EQ(s.references(1, 10), (Places{{1, 8}, {12, 13}}));
  EXPECT_EQ(s.signature(5, 17), (std::pair<std::string, int>{"LIMITW(OUT, IN, MAX)", 1}));
  EXPECT_EQ(s.signature(5, 23), (std::pair<std::string, int>{"LIMITW(OUT, IN, MAX)", 2}));
}

// PUP (shared/spec/akribis-drive.md): akribis.puh's names, #define naming a function number,
// #definevar, a task and a function, nested built-ins.
const char kPup[] =
    "// features\n"                   // 0
    "#include akribis.puh\n"          // 1
    "#define HOME_FN 1\n"             // 2
    "#definevar Speed AGenData[1]\n"  // 3
    "AProgTask[1]\n"                  // 4
    "AWaitStatus[MOTOR_READY], 0\n"   // 5
    "Speed = power(abs(Speed), 2)\n"  // 6
    "AProgFuncCall, HOME_FN\n"        // 7
    "AProgHalt[1]\n"                  // 8
    "AProgFunc[HOME_FN]\n"            // 9
    "Speed = sqrt(Speed)\n"           // 10
    "return\n";                       // 11

TEST(LspDialectFeatures, Pup) {
  Session s("file:///w/features.pup", "akribis-pup", kPup);
  ASSERT_EQ(s.diagnostics(), json::array()) << s.diagnostics().dump();
  EXPECT_EQ(s.outline(), (Names{"HOME_FN", "Speed", "task 1", "HOME_FN"}));
  EXPECT_EQ(s.folds(), (Places{{4, 8}, {9, 11}}));
  EXPECT_TRUE(has(s.hover(6, 1), "AGenData[1]")) << s.hover(6, 1);
  // builtin_header.h: #define MOTOR_READY 8, among the WaitStatus conditions.
  const std::string ready = s.hover(5, 14);
  EXPECT_TRUE(has(ready, "MOTOR_READY is 8") && has(ready, "AWaitStatus")) << ready;
  std::map<std::string, json> items = s.completion(6, 0);
  for (const char* name : {"Speed", "HOME_FN", "MOTOR_READY"}) EXPECT_TRUE(items.count(name));
  EXPECT_EQ(items["power"]["insertText"], "power(${1:a}, ${2:b})");
  EXPECT_EQ(s.definition(7, 17), (std::pair<int, int>{9, 10}));
  EXPECT_EQ(s.references(2, 9), (Places{{2, 8}, {7, 15}, {9, 10}}));
  EXPECT_EQ(s.signature(6, 20), (std::pair<std::string, int>{"abs(x)", 0}));
  EXPECT_EQ(s.signature(6, 26), (std::pair<std::string, int>{"power(a, b)", 1}));
}

}  // namespace
}  // namespace uprog::lsp
