// Runs every program in tests/vm/cases/. Each states what it expects in comment lines:
//   ; entry: NAME                 the routine to start (default: main)
//   ; entry number: N             ... or a routine by its number (for one the image lacks)
//   ; thread: N                   the thread to start it on (default: 0)
//   ; expect start: error NAME    Machine::start refuses it with that error; nothing runs
//   ; interrupt: NAME             after the first slice, enter routine NAME as an event
//   ; expect interrupt: error NAME    ... and the machine refuses that entry
//   ; expect end: finished | error NAME
//   ; expect NAME = VALUE         a global (NAME[i] for an element); VALUE int, or float with '.'
//   ; expect clock = N            the virtual time at the end, in µs
//   ; expect runs = N             how often the host's action command ran
//   ; expect counter reads = N    how often command 5, the host's read counter, was read
//   ; expect action index = N     the index of the last action command
//   ; expect slices = N           how many slices it took to the end
//   ; expect messages = N         how many messages the program sent
//   ; expect message K = T A...   message K (from 0) sent text T with int arguments A...
// Also checks that the cases together use every opcode but BREAK (tested in machine_test.cpp),
// and that every run-time error of src/vm/run_errors.def is produced by a case.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
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

std::optional<std::string> directive(const std::string& text, const char* pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) return std::nullopt;
  return m[1].str();
}

// One refusal the machine reports directly (from start or interrupt): the error a case expects
// of it (";" KIND ": error NAME"), or none.
void expect_refusal(const std::string& text, const char* kind, vm::RunError got) {
  const auto wanted =
      directive(text, (std::string("; expect ") + kind + R"(: error (\w+))").c_str());
  EXPECT_STREQ(vm::run_error_name(got), wanted.value_or("None").c_str()) << kind;
}

// Starts the case as its directives say and runs it to its end. False when the start was
// refused (then nothing ran).
bool run_as_directed(const std::string& text, LoadedProgram& p, uint32_t thread,
                     vm::SliceResult& r) {
  int routine = p.image.find_routine(directive(text, R"(; entry: (\w+))").value_or("main"));
  if (const auto number = directive(text, R"(; entry number: (\d+))")) routine = std::stoi(*number);
  EXPECT_GE(routine, 0);
  const vm::RunError started = p.machine.start(thread, static_cast<uint32_t>(routine));
  expect_refusal(text, "start", started);
  if (started != vm::RunError::None) return false;
  if (const auto event = directive(text, R"(; interrupt: (\w+))")) {
    p.machine.run_slice(thread, vm::Budget::unlimited());
    const int event_routine = p.image.find_routine(*event);
    EXPECT_GE(event_routine, 0) << *event;
    expect_refusal(text, "interrupt",
                   p.machine.interrupt(thread, static_cast<uint32_t>(event_routine)));
  }
  r = p.run_to_end(thread);
  return true;
}

TEST_P(VmCase, RunsAsExpected) {
  const std::string text = read(GetParam());
  LoadedProgram p;
  ASSERT_TRUE(p.load(text)) << "load failed: verify error " << static_cast<int>(p.status.verify)
                            << " at " << p.status.pc;
  const uint32_t thread =
      static_cast<uint32_t>(std::stoul(directive(text, R"(; thread: (\d+))").value_or("0")));
  vm::SliceResult r{};
  const bool ran = run_as_directed(text, p, thread, r);

  bool saw_end = !ran;  // a refused start is the case's end
  std::istringstream lines(text);
  std::smatch m;
  std::string line;
  while (std::getline(lines, line)) {
    if (std::regex_match(line, m, std::regex(R"(; expect end: finished\s*)"))) {
      saw_end = true;
      EXPECT_EQ(r.end, vm::SliceEnd::Finished)
          << "stopped by " << vm::run_error_name(p.machine.last_error(thread)) << " at "
          << p.machine.pc(thread);
    } else if (std::regex_match(line, m, std::regex(R"(; expect end: error (\w+)\s*)"))) {
      saw_end = true;
      EXPECT_EQ(r.end, vm::SliceEnd::Error);
      EXPECT_STREQ(vm::run_error_name(p.machine.last_error(thread)), m[1].str().c_str());
    } else if (std::regex_match(line, m, std::regex(R"(; expect clock = (\d+)\s*)"))) {
      EXPECT_EQ(p.host.clock_us, std::stoul(m[1]));
    } else if (std::regex_match(line, m, std::regex(R"(; expect runs = (\d+)\s*)"))) {
      EXPECT_EQ(p.host.runs, std::stoi(m[1]));
    } else if (std::regex_match(line, m, std::regex(R"(; expect counter reads = (\d+)\s*)"))) {
      EXPECT_EQ(p.host.counter_reads, std::stoi(m[1]));
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
                   line, m,
                   std::regex(R"(; expect (\w+)(?:\[(\d+)\])? = (-?[0-9.eE+-]+|nan)\s*)"))) {
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
  EXPECT_TRUE(saw_end) << "a case must say how it ends (or that its start is refused)";
}

INSTANTIATE_TEST_SUITE_P(Cases, VmCase, ::testing::ValuesIn(case_files()),
                         [](const auto& param_info) { return param_info.param.stem().string(); });

TEST(VmCases, TogetherUseEveryOpcode) {
  std::set<std::string> used;
  for (const auto& f : case_files()) {
    bytecode::Image image;
    std::vector<Diagnostic> errors;
    ASSERT_TRUE(bytecode::assemble(read(f), f.string(), image, errors)) << f;
    for (uint32_t pc = 0; pc < image.code.size();
         pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
      used.insert(bytecode::op_name(bytecode::word_op(image.code[pc])));
  }
  for (uint32_t i = 0; i < bytecode::kOpCount; ++i) {
    const std::string name = bytecode::kOpNames[i];
    if (name == "BREAK") continue;
    EXPECT_TRUE(used.count(name)) << "no case in tests/vm/cases uses " << name;
  }
}

// Like the verifier's bad images: a run-time error no case produces is an untested promise.
// A case produces an error when it ends with it, or when the machine refuses its start or its
// event entry with it (the runner above checks each of these).
TEST(VmCases, ProduceEveryRunError) {
  std::set<std::string> produced;
  const std::regex produces(R"(; expect (?:end|start|interrupt): error (\w+))");
  for (const auto& f : case_files()) {
    const std::string text = read(f);
    for (std::sregex_iterator it(text.begin(), text.end(), produces), end; it != end; ++it)
      produced.insert((*it)[1].str());
  }
  const char* const registered[] = {
#define RUN_ERROR(name, code, text) #name,
#include "vm/run_errors.def"
#undef RUN_ERROR
  };
  for (const std::string name : registered) {
    if (name == "None") continue;  // not an error
    EXPECT_TRUE(produced.count(name)) << "no case in tests/vm/cases produces " << name;
  }
}

}  // namespace
}  // namespace uprog::test
