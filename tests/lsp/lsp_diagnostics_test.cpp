// Diagnostics of every registered dialect's documents: on open at once, on change once the
// debounce has passed, with the dialect's registered code and text (its error table, from its
// manual) over the word the compiler names; the dialect chosen by languageId or by extension;
// an error inside an #include'd file shown on the #include line, its place as related information.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lsp_client.h"

namespace uprog::lsp {
namespace {

namespace fs = std::filesystem;

// One program per dialect that uses a name it never declares, the dialect's code for that
// (its error table), and the vendor's languageId as editors/vscode names it.
struct UndeclaredCase {
  std::string dialect;
  std::string language_id;
  std::string extension;
  std::string text;
  std::string missing;  // the undeclared name in `text`
  std::string fix;      // what makes the program compile in its place
  int code;
};

const UndeclaredCase kCases[] = {
    // Gold 12 "No such variable" (manual 2.7.2).
    {"gold", "elmo-gold", ".ehl", "int done\nfunction main()\ndone = missing\nreturn\n", "missing",
     "6 * 7", 12},
    // PDL 20 "unknown name" (src/dialects/pdl/errors.def: the spec's 20-39 band of names).
    {"pdl", "hiwin-pdl", ".pdl", "#long done\n#task/1;\ndone = missing;\nhalt;\n", "missing",
     "6 * 7", 20},
    // PUP 2 "unknown name" (src/dialects/pup/pup_errors.def).
    {"pup", "akribis-pup", ".pup",
     "#definevar Done AGenData[1]\nAProgTask[1]\nDone = Missing\nAProgHalt[1]\n", "Missing",
     "6 * 7", 2},
    // ST 11 "variable not declared" (src/dialects/st/st_errors.def).
    {"st", "kollmorgen-st", ".st",
     "LONG DONE ;\nPROGRAM PLCMAIN\n   DONE := MISSING;\nEND_PROGRAM\n", "MISSING", "6 * 7", 11},
};

void PrintTo(const UndeclaredCase& k, std::ostream* os) { *os << k.dialect; }

std::string registered_text(const std::string& dialect, int code) {
  for (const dialect::ErrorInfo& e : dialects::find(dialect)->diagnostic_codes())
    if (e.code == code) return std::string(e.text);
  return "<no such code>";
}

class LspDiagnostics : public ::testing::TestWithParam<UndeclaredCase> {};

TEST_P(LspDiagnostics, OnOpenWithTheDialectsCodeAndText) {
  const UndeclaredCase& k = GetParam();
  LspClient c;
  c.initialize();
  const std::string uri = "file:///work/prog" + k.extension;
  const json p = c.open(uri, k.language_id, k.text, 7);
  ASSERT_FALSE(p.is_null());
  EXPECT_EQ(p["uri"], uri);
  EXPECT_EQ(p["version"], 7);
  ASSERT_GE(p["diagnostics"].size(), 1u) << p.dump();
  const json& d = p["diagnostics"][0];
  EXPECT_EQ(d["code"], k.code);
  EXPECT_EQ(d["severity"], 1);
  EXPECT_EQ(d["source"], "uprog " + k.dialect);
  const std::string message = d["message"];
  EXPECT_EQ(message.rfind(registered_text(k.dialect, k.code), 0), 0u) << message;
  // The range is the undeclared name's, where the text has it (line 2, 0-based).
  const size_t line_start = k.text.find('\n', k.text.find('\n') + 1) + 1;
  const auto column = static_cast<int64_t>(k.text.find(k.missing) - line_start);
  EXPECT_EQ(d["range"]["start"], (json{{"line", 2}, {"character", column}}));
  EXPECT_EQ(d["range"]["end"],
            (json{{"line", 2}, {"character", column + static_cast<int64_t>(k.missing.size())}}));
}

TEST_P(LspDiagnostics, ChangesAreDebouncedThenChecked) {
  const UndeclaredCase& k = GetParam();
  LspClient c;
  c.initialize();
  const std::string uri = "file:///work/prog" + k.extension;
  c.open(uri, k.language_id, k.text);
  const size_t line_start = k.text.find('\n', k.text.find('\n') + 1) + 1;
  const auto column = static_cast<int64_t>(k.text.find(k.missing) - line_start);
  const json range = {
      {"start", {{"line", 2}, {"character", column}}},
      {"end", {{"line", 2}, {"character", column + static_cast<int64_t>(k.missing.size())}}}};
  std::vector<json> out = c.notify("textDocument/didChange",
                                   {{"textDocument", {{"uri", uri}, {"version", 2}}},
                                    {"contentChanges", {{{"range", range}, {"text", k.fix}}}}});
  EXPECT_TRUE(published(out).is_null());  // not before the debounce has passed
  EXPECT_TRUE(published(c.wait(100)).is_null());
  const json p = published(c.wait(50));
  ASSERT_FALSE(p.is_null());
  EXPECT_EQ(p["version"], 2);
  EXPECT_EQ(p["diagnostics"], json::array()) << p.dump();
  // Closed: its diagnostics are cleared.
  const json closed =
      published(c.notify("textDocument/didClose", {{"textDocument", {{"uri", uri}}}}));
  EXPECT_EQ(closed["diagnostics"], json::array());
}

TEST_P(LspDiagnostics, TheDialectComesFromTheExtensionWhenTheLanguageIdNamesNone) {
  const UndeclaredCase& k = GetParam();
  LspClient c;
  c.initialize();
  const json p = c.open("file:///work/other" + k.extension, "plaintext", k.text);
  ASSERT_FALSE(p.is_null());
  EXPECT_EQ(p["diagnostics"].at(0)["source"], "uprog " + k.dialect);
  // And the short name is a languageId too (Neovim's filetype).
  const json q = c.open("file:///work/untitled", k.dialect, k.text);
  ASSERT_FALSE(q.is_null());
  EXPECT_EQ(q["diagnostics"].at(0)["code"], k.code);
}

INSTANTIATE_TEST_SUITE_P(EveryDialect, LspDiagnostics, ::testing::ValuesIn(kCases),
                         [](const auto& c) { return c.param.dialect; });

TEST(LspDiagnostics, EveryRegisteredDialectHasACase) {
  for (const dialect::Dialect* d : dialects::all()) {
    bool found = false;
    for (const UndeclaredCase& k : kCases) found = found || k.dialect == d->name();
    EXPECT_TRUE(found) << d->name();
  }
}

TEST(LspDiagnostics, AnErrorInAnIncludedFileIsShownOnTheIncludeLine) {
  const fs::path dir = fs::temp_directory_path() / "uprog_lsp_include";
  fs::create_directories(dir);
  // PDL 1 "syntax error" (errors.def) at bad.h's line 2, column 10 (the ';' where a value is due).
  std::ofstream(dir / "bad.h") << "#long shared\nshared = ;\n";
  const std::string main_text = "#task/1;\n#include \"bad.h\"\nhalt;\n";
  LspClient c;
  c.initialize();
  const json p = c.open("file://" + (dir / "main.pdl").string(), "hiwin-pdl", main_text);
  ASSERT_FALSE(p.is_null());
  ASSERT_EQ(p["diagnostics"].size(), 1u) << p.dump();
  const json& d = p["diagnostics"][0];
  EXPECT_EQ(d["code"], 1);
  EXPECT_EQ(d["range"]["start"]["line"], 1);  // the #include line
  EXPECT_EQ(d["range"]["end"]["character"], 16);
  ASSERT_EQ(d["relatedInformation"].size(), 1u);
  const json& related = d["relatedInformation"][0];
  EXPECT_EQ(related["location"]["uri"], "file://" + (dir / "bad.h").string());
  EXPECT_EQ(related["location"]["range"]["start"], (json{{"line", 1}, {"character", 9}}));
  // The header fixed on disk: a watched-file change checks the document again, now clean.
  std::ofstream(dir / "bad.h") << "#long shared\nshared = 1;\n";
  c.notify("workspace/didChangeWatchedFiles",
           {{"changes", {{{"uri", "file://" + (dir / "bad.h").string()}, {"type", 2}}}}});
  const json again = published(c.wait(0));
  ASSERT_FALSE(again.is_null());
  EXPECT_EQ(again["diagnostics"], json::array()) << again.dump();
  fs::remove_all(dir);
}

TEST(LspDiagnostics, GoToAProcedureOfAnIncludedFile) {
  const fs::path dir = fs::temp_directory_path() / "uprog_lsp_include_definition";
  fs::create_directories(dir);
  // A procedure in the header (manual 1.4, 2.5.6), called from the document.
  std::ofstream(dir / "twice.h")
      << "// doubles\nproc twice(long x, long* out) do\n  *out=x*2;\nend;\n";
  const std::string main_text =
      "#include \"twice.h\"\n#long v, w\n#task/1;\ntwice(v, &w);\nhalt;\n";
  LspClient c;
  c.initialize();
  const std::string uri = "file://" + (dir / "main.pdl").string();
  const json p = c.open(uri, "hiwin-pdl", main_text);
  ASSERT_EQ(p["diagnostics"], json::array()) << p.dump();
  const std::vector<json> out =
      c.request("textDocument/definition",
                {{"textDocument", {{"uri", uri}}}, {"position", {{"line", 3}, {"character", 1}}}});
  ASSERT_EQ(out.size(), 1u);
  const json& where = out[0]["result"];
  EXPECT_EQ(where["uri"], "file://" + (dir / "twice.h").string());
  EXPECT_EQ(where["range"]["start"], (json{{"line", 1}, {"character", 5}}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace uprog::lsp
