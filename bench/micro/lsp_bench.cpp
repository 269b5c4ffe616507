// The language server's diagnostics for a 10 000-line document (issue 45: within 100 ms of a
// change): one didChange (a character typed) and the publishDiagnostics that follows once the
// debounce (0 here) has passed, per dialect. The document is the dialect's simplest statement
// line repeated; what the compiler says of it is published whole, as an editor would get it.
#include <benchmark/benchmark.h>

#include <nlohmann/json.hpp>
#include <string>

#include "dialects/registry.h"
#include "lsp/lsp_server.h"

namespace {

using json = nlohmann::json;
constexpr int kLines = 10'000;

struct Document {
  const char* dialect;
  const char* head;  // declarations and the start of the program
  const char* line;  // repeated to make kLines lines
  const char* tail;
};

constexpr Document kDocuments[] = {
    {"gold", "int x\nfunction main()\n", "x = x + 1\n", "return\n"},
    {"pdl", "#long x\n#task/1;\n", "x=x+1;\n", "halt;\n"},
    {"pup", "#definevar X AGenData[1]\nAProgTask[1]\n", "X = X + 1\n", "AProgHalt[1]\n"},
    {"st", "LONG X;\nPROGRAM PLCMAIN\n", "  X := X + 1;\n", "END_PROGRAM\n"},
};

void BM_LspDiagnosticsAfterChange(benchmark::State& state) {
  const Document& d = kDocuments[state.range(0)];
  std::string text = d.head;
  for (int i = 3; i < kLines; ++i) text += d.line;
  text += d.tail;
  size_t published = 0, bytes = 0;
  uprog::lsp::LspOptions options;
  for (const uprog::dialect::Dialect* each : uprog::dialects::all())
    options.dialects.push_back(each);
  options.debounce_ms = 0;
  uprog::lsp::LspServer server(std::move(options), [&](const std::string& m) {
    ++published;
    bytes += m.size();
  });
  server.handle(R"({"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}})");
  const std::string uri = std::string("file:///bench/doc.") + d.dialect;
  server.handle(
      json{{"jsonrpc", "2.0"},
           {"method", "textDocument/didOpen"},
           {"params",
            {{"textDocument",
              {{"uri", uri}, {"languageId", d.dialect}, {"version", 1}, {"text", text}}}}}}
          .dump());
  int64_t version = 1;
  for (auto _ : state) {
    // A blank typed at the end of line 5000, then checked.
    const json change = {{"jsonrpc", "2.0"},
                         {"method", "textDocument/didChange"},
                         {"params",
                          {{"textDocument", {{"uri", uri}, {"version", ++version}}},
                           {"contentChanges",
                            {{{"range",
                               {{"start", {{"line", 5000}, {"character", 0}}},
                                {"end", {{"line", 5000}, {"character", 0}}}}},
                              {"text", " "}}}}}}};
    server.handle(change.dump());
    server.poll();
  }
  state.counters["published_bytes"] = static_cast<double>(bytes) / static_cast<double>(published);
  state.SetLabel(d.dialect);
}
BENCHMARK(BM_LspDiagnosticsAfterChange)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace
