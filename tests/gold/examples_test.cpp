// Every program in examples/gold compiles without a diagnostic, and produces code.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dialects/gold/compile.h"
#include "gold_runner.h"

namespace fs = std::filesystem;

TEST(gold_examples, AllCompileClean) {
  const fs::path dir = fs::path(UPROG_SOURCE_DIR) / "examples/gold";
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".ehl") continue;
    ++n;
    std::ifstream in(e.path());
    std::stringstream ss;
    ss << in.rdbuf();
    const auto r = uprog::gold::compile(uprog::SourceFile{e.path().filename().string(), ss.str()});
    EXPECT_TRUE(r.diagnostics.empty()) << uprog::format_text(r.diagnostics);
    EXPECT_FALSE(r.image.code.empty()) << e.path();
    // The VM's verifier accepts what the compiler made.
    uprog::gold_test::GoldRun run;
    EXPECT_TRUE(run.load(r.image)) << e.path();
  }
  EXPECT_GE(n, 12u);
}
