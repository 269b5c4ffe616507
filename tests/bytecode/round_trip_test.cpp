// The two forms of an image round-trip exactly: assembly → image → binary → image → assembly
// → image gives the same image and the same bytes, for every assembly file in the tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "bytecode/opcodes.h"
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
  ASSERT_TRUE(assemble(read(GetParam()), GetParam().string(), first, errors))
      << format_text(errors);
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
  image.constants = {{ValueType::Int, 0xFFFFFFFFu},
                     {ValueType::Float, 0x7FC00000u},
                     {ValueType::Float, 0x3DCCCCCDu},
                     {ValueType::Float, 0x80000000u}};
  image.globals = {{"a", ValueType::Int, 1}, {"b", ValueType::Float, 2040}};
  image.code = {0x00000001u, 0x0000FF00u, 0xFFFFFFFFu, 0x00000000u};  // includes raw words
  image.routines = {
      {"main", RoutineKind::Function, 1, 1, {{"x", ValueType::Int}, {"y", ValueType::Float}}, 0},
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

TEST(RoundTrip, DialectTextsAndTasks) {
  Image image;
  image.dialect = "st";
  image.code = {make_word(Op::RET, 0)};
  image.routines = {{"PLCINIT", RoutineKind::Task, 0, 0, {}, 0},
                    {"PLC62", RoutineKind::Task, 0, 0, {}, 0}};
  image.texts = {"x=%d\n", "quote \" and \\", ""};
  // 62.5 us exactly; a period past 4 s still fits; the last task names no routine of its own.
  image.tasks = {{0, 0, 0, 0, true}, {1, 62, 62500, 256, false}, {1, 7, UINT32_MAX, 1, true}};
  const auto bytes = encode(image);
  Image decoded;
  std::string error;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), decoded, error)) << error;
  EXPECT_EQ(decoded, image);
  const std::string text = disassemble(decoded);
  EXPECT_NE(text.find(".dialect \"st\""), std::string::npos) << text;
  EXPECT_NE(text.find(".task 1 number=62 period_ns=62500 priority=256 start_at_reset=0"),
            std::string::npos)
      << text;
  Image again;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(assemble(text, "t", again, errors)) << format_text(errors) << text;
  EXPECT_EQ(again, image) << text;
}

TEST(Assembler, TasksNameTheirRoutine) {
  Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(
      assemble(".task \"b\" number=2 period_ns=1000000 priority=4 start_at_reset=1\n"
               ".routine task \"a\" in=0 out=0 entry=m\n"
               ".routine task \"b\" in=0 out=0 entry=m\nm:\n  RET\n",
               "t", image, errors))
      << format_text(errors);
  ASSERT_EQ(image.tasks.size(), 1u);
  EXPECT_EQ(image.tasks[0], (Task{1, 2, 1000000, 4, true}));
  EXPECT_FALSE(
      assemble(".task nope number=0 period_ns=0 priority=0 start_at_reset=0\n"
               ".task 0 number=0 period_ns=0 priority=0 start_at_reset=2\n"
               ".task 0 number=0 period=0 priority=0 start_at_reset=0\n"
               ".routine task \"a\" in=0 out=0 entry=m\nm:\n  RET\n",
               "bad.s", image, errors));
  ASSERT_EQ(errors.size(), 3u) << format_text(errors);
  EXPECT_NE(errors[0].message.find("unknown routine 'nope'"), std::string::npos);
  EXPECT_EQ(errors[1].where.line, 2);
  EXPECT_EQ(errors[2].where.line, 3);
}

TEST(Assembler, ReportsErrorsWithTheirPlace) {
  Image image;
  std::vector<Diagnostic> errors;
  EXPECT_FALSE(assemble("  PUSHI 99999999\n  BOGUS\n  JMP nowhere\n.const float x\n", "bad.s",
                        image, errors));
  ASSERT_EQ(errors.size(), 4u);
  EXPECT_EQ(format_text(errors[0]).rfind("bad.s:1:9: error:", 0), 0u) << format_text(errors[0]);
  EXPECT_EQ(errors[1].where.line, 2);
  EXPECT_NE(errors[1].message.find("BOGUS"), std::string::npos);
  EXPECT_EQ(errors[3].where.line, 4);
  EXPECT_EQ(errors[2].where.line, 3);
}

}  // namespace
}  // namespace uprog::bytecode
