// Runs every program in tests/vm/cases/. Each states what it expects in comment lines:
//   ; entry: NAME                 the routine to start (default: main)
//   ; expect end: finished | error NAME
//   ; expect NAME = VALUE         a global (NAME[i] for an element); VALUE int, or float with '.'
//   ; expect clock = N            the virtual time at the end, in µs
//   ; expect runs = N             how often the host's action command ran
//   ; expect action index = N     the index of the last action command
//   ; expect slices = N           how many slices it took to the end
//   ; expect messages = N         how many messages the program sent
//   ; expect message K = T A...   message K (from 0) sent text T with int arguments A...
// Also checks that the cases together use every opcode but BREAK (tested in machine_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "bytecode/opcodes.h"
#include "testlib/test_files.h"
#include "vm_fixture.h"

namespace uprog::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> case_files() { return source_files("tests/vm/cases", ".s"); }
std::string read(const fs::path& p) { return read_whole(p); }

class VmCase : public ::testing::TestWithParam<fs::path> {};

TEST_P(VmCase, RunsAsExpected) {
  const std::string text = read(GetParam());
  LoadedProgram p;
  ASSERT_TRUE(p.load(text)) << "load failed: verify error " << static_cast<int>(p.status.verify)
                            << " at " << p.status.pc;
  std::smatch m;
  std::string entry = "main";
  if (std::regex_search(text, m, std::regex(R"(; entry: (\w+))"))) entry = m[1];
  const int routine = p.image.find_routine(entry);
  ASSERT_GE(routine, 0);
  ASSERT_EQ(p.machine.start(0, static_cast<uint32_t>(routine)), vm::RunError::None);
  const vm::SliceResult r = p.run_to_end();

  bool saw_end = false;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (std::regex_match(line, m, std::regex(R"(; expect end: finished\s*)"))) {
      saw_end = true;
      EXPECT_EQ(r.end, vm::SliceEnd::Finished)
          << "stopped by " << vm::run_error_name(p.machine.last_error(0)) << " at "
          << p.machine.pc(0);
    } else if (std::regex_match(line, m, std::regex(R"(; expect end: error (\w+)\s*)"))) {
      saw_end = true;
      EXPECT_EQ(r.end, vm::SliceEnd::Error);
      EXPECT_STREQ(vm::run_error_name(p.machine.last_error(0)), m[1].str().c_str());
    } else if (std::regex_match(line, m, std::regex(R"(; expect clock = (\d+)\s*)"))) {
      EXPECT_EQ(p.host.clock_us, std::stoul(m[1]));
    } else if (std::regex_match(line, m, std::regex(R"(; expect runs = (\d+)\s*)"))) {
      EXPECT_EQ(p.host.runs, std::stoi(m[1]));
    } else if (std::regex_match(line, m, std::regex(R"(; expect action index = (-?\d+)\s*)"))) {
      EXPECT_EQ(p.host.action_index, std::stoi(m[1]));
    } else if (std::regex_match(line, m, std::regex(R"(; expect slices = (\d+)\s*)"))) {
      EXPECT_EQ(p.slices, std::stoull(m[1]));
    } else if (std::regex_match(line, m, std::regex(R"(; expect messages = (\d+)\s*)"))) {
      EXPECT_EQ(p.host.message_count, std::stoul(m[1]));
    } else if (std::regex_match(line, m,
                                std::regex(R"(; expect message (\d+) = (\d+)((?: -?\d+)*)\s*)"))) {
      const size_t k = std::stoul(m[1]);
      ASSERT_LT(k, std::min(p.host.message_count, ScriptedHost::kKeptMessages)) << line;
      EXPECT_EQ(p.host.messages[k].text, std::stoul(m[2])) << line;
      std::vector<int32_t> args;
      std::istringstream words(m[3].str());
      for (int32_t a; words >> a;) args.push_back(a);
      EXPECT_EQ(p.host.messages[k].arguments(), args) << line;
    } else if (std::regex_match(
                   line, m, std::regex(R"(; expect (\w+)(?:\[(\d+)\])? = (-?[0-9.eE+-]+|nan)\s*)"))) {
      const uint32_t element = m[2].matched ? static_cast<uint32_t>(std::stoul(m[2])) : 0;
      const Value v = p.global(m[1], element);
      const std::string want = m[3];
      if (want.find_first_of(".en") != std::string::npos) {
        EXPECT_EQ(v.f, std::stof(want)) << line;
      } else {
        EXPECT_EQ(v.i, std::stol(want)) << line;
      }
    }
  }
  EXPECT_TRUE(saw_end) << "a case must say how it ends";
}

INSTANTIATE_TEST_SUITE_P(Cases, VmCase, ::testing::ValuesIn(case_files()),
                         [](const auto& param_info) { return param_info.param.stem().string(); });

TEST(VmCases, TogetherUseEveryOpcode) {
  std::set<std::string> used;
  for (const auto& f : case_files()) {
    bytecode::Image image;
    std::vector<Diagnostic> errors;
    ASSERT_TRUE(bytecode::assemble(read(f), f.string(), image, errors)) << f;
    for (uint32_t pc = 0; pc < image.code.size(); pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
      used.insert(bytecode::op_name(bytecode::word_op(image.code[pc])));
  }
  for (uint32_t i = 0; i < bytecode::kOpCount; ++i) {
    const std::string name = bytecode::kOpNames[i];
    if (name == "BREAK") continue;
    EXPECT_TRUE(used.count(name)) << "no case in tests/vm/cases uses " << name;
  }
}

}  // namespace
}  // namespace uprog::test
