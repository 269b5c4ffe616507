// The two forms of an image round-trip exactly: assembly → image → binary → image → assembly
// → image gives the same image and the same bytes, for every assembly file in the tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "testlib/test_files.h"

namespace uprog::bytecode {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> assembly_files() {
  std::vector<fs::path> files;
  for (const char* dir : {"tests/vm/cases", "tests/bytecode/bad", "examples/asm"})
    for (const auto& f : test::source_files(dir, ".s")) files.push_back(f);
  return files;
}

std::string read(const fs::path& p) { return test::read_whole(p); }

class RoundTrip : public ::testing::TestWithParam<fs::path> {};

TEST_P(RoundTrip, AssemblyBinaryAssembly) {
  Image first;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(assemble(read(GetParam()), GetParam().string(), first, errors)) << format_text(errors);
  const std::vector<uint8_t> bytes = encode(first);
  Image decoded;
  std::string error;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), decoded, error)) << error;
  EXPECT_EQ(decoded, first);
  const std::string text = disassemble(decoded);
  Image again;
  ASSERT_TRUE(assemble(text, "disassembled", again, errors)) << format_text(errors) << text;
  EXPECT_EQ(again, first);
  EXPECT_EQ(encode(again), bytes);
  EXPECT_EQ(disassemble(again), text);
}

INSTANTIATE_TEST_SUITE_P(Files, RoundTrip, ::testing::ValuesIn(assembly_files()),
                         [](const auto& param_info) { return param_info.param.stem().string(); });

TEST(RoundTrip, EveryPartOfAnImage) {
  Image image;
  image.created_unix_s = 0x123456789ull;
  image.source_name = "odd \"name\"\n\x01.ehl";
  image.info = {"dialect=gold", "entry=main"};
  image.constants = {{ValueType::Int, 0xFFFFFFFFu}, {ValueType::Float, 0x7FC00000u},
                     {ValueType::Float, 0x3DCCCCCDu}, {ValueType::Float, 0x80000000u}};
  image.globals = {{"a", ValueType::Int, 1}, {"b", ValueType::Float, 2040}};
  image.code = {0x00000001u, 0x0000FF00u, 0xFFFFFFFFu, 0x00000000u};  // includes raw words
  image.routines = {{"main", RoutineKind::Function, 1, 1, {{"x", ValueType::Int}, {"y", ValueType::Float}}, 0},
                    {"AUTO_ER", RoutineKind::AutoRoutine, 0, 0, {}, 3},
                    {"task", RoutineKind::Task, 0, 0, {}, 1},
                    {"lbl", RoutineKind::Label, 0, 0, {}, 2}};
  image.events = {{7, 1}};
  image.lines = {{0, "a.ehl", 3}, {2, "b.ehl", 4}, {4, "a.ehl", 9}};
  const auto bytes = encode(image);
  Image decoded;
  std::string error;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), decoded, error)) << error;
  EXPECT_EQ(decoded, image);
  Image again;
  std::vector<Diagnostic> errors;
  const std::string text = disassemble(decoded);
  ASSERT_TRUE(assemble(text, "t", again, errors)) << format_text(errors) << text;
  EXPECT_EQ(again, image) << text;
}

TEST(Assembler, ReportsErrorsWithTheirPlace) {
  Image image;
  std::vector<Diagnostic> errors;
  EXPECT_FALSE(assemble("  PUSHI 99999999\n  BOGUS\n  JMP nowhere\n.const float x\n", "bad.s", image, errors));
  ASSERT_EQ(errors.size(), 4u);
  EXPECT_EQ(format_text(errors[0]).rfind("bad.s:1:9: error:", 0), 0u) << format_text(errors[0]);
  EXPECT_EQ(errors[1].where.line, 2);
  EXPECT_NE(errors[1].message.find("BOGUS"), std::string::npos);
  EXPECT_EQ(errors[3].where.line, 4);
  EXPECT_EQ(errors[2].where.line, 3);
}

}  // namespace
}  // namespace uprog::bytecode
