// Machine::run_round: a drive's round of one-line turns in one entry into the execute loop, and
// where it must end so that the schedule sees what a line changed before the next thread runs.
#include <gtest/gtest.h>

#include "vm_fixture.h"

namespace uprog::test {
namespace {

using vm::Budget;
using vm::Round;
using vm::SliceEnd;

// Threads 1..3 each run a routine whose line appends its digit to `order` (order = order * 10 +
// digit), so the global spells the order in which the lines ran. Thread 2's routine `reads`
// calls the host in its line; `ends` has its program's bare end after its line; `fails` raises.
const char* kTurns = R"(
.global int "order" 1
.routine function "one" in=0 out=0 entry=one
.routine function "two" in=0 out=0 entry=two
.routine function "three" in=0 out=0 entry=three
.routine function "reads" in=0 out=0 entry=reads
.routine function "ends" in=0 out=0 entry=ends
.routine function "fails" in=0 out=0 entry=fails
one:
  LDG order
  PUSHI 10
  MULI
  PUSHI 1
  ADDI
  STG order
  EOL
  JMP one
two:
  LDG order
  PUSHI 10
  MULI
  PUSHI 2
  ADDI
  STG order
  EOL
  JMP two
three:
  LDG order
  PUSHI 10
  MULI
  PUSHI 3
  ADDI
  STG order
  EOL
  JMP three
reads:
  LDG order
  PUSHI 10
  MULI
  PUSHI 2
  ADDI
  STG order
  CMDGET 1 0
  POP
  EOL
  JMP reads
ends:
  LDG order
  PUSHI 10
  MULI
  PUSHI 1
  ADDI
  STG order
  EOL
  EXIT
fails:
  RAISE 1
)";

constexpr uint32_t kOne = 0, kTwo = 1, kThree = 2, kReads = 3, kEnds = 4, kFails = 5;
const Budget kOneLine{0, 1, 1000};

struct Turns : LoadedProgram {
  // Loads kTurns and starts thread t (1..3) at routines[t - 1].
  bool begin(std::initializer_list<uint32_t> routines) {
    if (!load(kTurns)) return false;
    uint32_t thread = 1;
    for (uint32_t r : routines) {
      if (machine.start(thread++, r) != vm::RunError::None) return false;
    }
    return true;
  }
};

constexpr uint32_t kThreads = 0b1110;  // threads 1, 2 and 3
constexpr uint32_t kFirstTwo = 0b0110;

TEST(Round, RunsEachThreadsLineInOrder) {
  Turns p;
  ASSERT_TRUE(p.begin({kOne, kTwo, kThree}));
  Round round{kThreads};
  const auto r = p.machine.run_round(round, kOneLine);
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(r.lines, 1u);
  EXPECT_EQ(round.at, 3u);
  EXPECT_EQ(p.global("order").i, 123);
  // Each thread stopped just after its own EOL, at its JMP, as a slice of one line leaves it.
  EXPECT_EQ(p.machine.pc(1), 7u);
  EXPECT_EQ(p.machine.pc(2), 15u);
  EXPECT_EQ(p.machine.pc(3), 23u);
  EXPECT_EQ(p.machine.run_round(round, kOneLine).end, SliceEnd::LineEnd);
  EXPECT_EQ(p.global("order").i, 123123);
}

TEST(Round, ALineThatCallsTheHostEndsIt) {
  Turns p;
  ASSERT_TRUE(p.begin({kOne, kReads, kThree}));
  Round round{kThreads};
  const auto r = p.machine.run_round(round, kOneLine);
  EXPECT_EQ(r.end, SliceEnd::LineEnd);
  EXPECT_EQ(round.at,
            2u);  // thread 2's line ran whole; thread 3 is the schedule's to look at again
  EXPECT_EQ(p.global("order").i, 12);
}

TEST(Round, ItEndsBeforeAThreadThatCannotStartInIt) {
  Turns p;
  ASSERT_TRUE(p.begin({kOne, kTwo, kThree}));
  p.machine.halt(2);
  Round round{kThreads};
  EXPECT_EQ(p.machine.run_round(round, kOneLine).end, SliceEnd::LineEnd);
  EXPECT_EQ(round.at, 1u);
  EXPECT_EQ(p.global("order").i, 1);
  // Its first thread not running: nothing runs.
  Round second{0b1100};  // threads 2 and 3
  const auto r = p.machine.run_round(second, kOneLine);
  EXPECT_EQ(r.end, SliceEnd::NotRunning);
  EXPECT_EQ(r.executed, 0u);
  EXPECT_EQ(second.at, 2u);
  EXPECT_EQ(p.global("order").i, 1);
}

// A thread the machine does not have (it has four) ends the round as a stopped one does.
TEST(Round, ItEndsBeforeAThreadTheMachineLacks) {
  Turns p;
  ASSERT_TRUE(p.begin({kOne, kTwo}));
  Round round{kFirstTwo | 1u << 9};
  EXPECT_EQ(p.machine.run_round(round, kOneLine).end, SliceEnd::LineEnd);
  EXPECT_EQ(round.at, 2u);
  EXPECT_EQ(p.global("order").i, 12);
  Round beyond{1u << 31};
  EXPECT_EQ(p.machine.run_round(beyond, kOneLine).end, SliceEnd::NotRunning);
  EXPECT_EQ(beyond.at, 31u);
  EXPECT_EQ(p.global("order").i, 12);
}

TEST(Round, ItEndsBeforeAProgramsBareEnd) {
  Turns p;
  ASSERT_TRUE(p.begin({kEnds, kTwo}));
  Round round{kFirstTwo};
  EXPECT_EQ(p.machine.run_round(round, kOneLine).end, SliceEnd::LineEnd);
  EXPECT_EQ(round.at, 1u);
  EXPECT_TRUE(p.machine.at_bare_end(1));  // the EXIT is the schedule's to run with the line
  EXPECT_EQ(p.machine.status(1), vm::ThreadStatus::Running);
  EXPECT_EQ(p.global("order").i, 1);
}

TEST(Round, ASliceThatEndsOtherwiseEndsIt) {
  Turns p;
  ASSERT_TRUE(p.begin({kFails, kTwo}));
  Round round{kFirstTwo};
  EXPECT_EQ(p.machine.run_round(round, kOneLine).end, SliceEnd::Error);
  EXPECT_EQ(round.at, 1u);
  EXPECT_EQ(p.global("order").i, 0);
}

TEST(Round, ItCountsNoInstructions) {
  Turns p;
  ASSERT_TRUE(p.begin({kOne, kTwo}));
  Round round{kFirstTwo};
  EXPECT_EQ(p.machine.run_round(round, Budget{10, 1, 1000}).end, SliceEnd::NotRunning);
  EXPECT_EQ(p.global("order").i, 0);
}

// A host that, in a read, runs thread 3's line as a slice of its own (a firmware may run a
// slice from inside a call): that slice must not go on with the round.
class NestingHost final : public vm::Host {
 public:
  vm::Machine* machine = nullptr;
  vm::SliceResult nested{};
  vm::CommandStatus read(uint32_t, int32_t, Value& out) override {
    nested = machine->run_slice(3, kOneLine);
    out = Value::of_int(0);
    return vm::kCommandOk;
  }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return 21; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override { return 21; }
  vm::CommandStatus message(uint32_t, uint32_t, const Value*, uint32_t) override { return 21; }
  uint32_t now_us() override { return 0; }
};

TEST(Round, ASliceRunFromInsideAHostCallRunsAlone) {
  bytecode::Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(bytecode::assemble(kTurns, "test.s", image, errors));
  const std::vector<uint8_t> bytes = bytecode::encode(image);
  bytecode::ImageView view;
  ASSERT_EQ(bytecode::load_image(bytes.data(), bytes.size(), view), bytecode::LoadError::Ok);
  std::vector<uint64_t> memory(vm::Machine::memory_needed(view, {}) / 8 + 1, 0);
  NestingHost host;
  vm::Machine machine;
  host.machine = &machine;
  ASSERT_TRUE(
      machine.load(bytes.data(), bytes.size(), {}, memory.data(), memory.size() * 8, host).ok());
  ASSERT_EQ(machine.start(1, kOne), vm::RunError::None);
  ASSERT_EQ(machine.start(2, kReads), vm::RunError::None);
  ASSERT_EQ(machine.start(3, kThree), vm::RunError::None);
  Round round{kThreads};
  EXPECT_EQ(machine.run_round(round, kOneLine).end, SliceEnd::LineEnd);
  EXPECT_EQ(host.nested.end, SliceEnd::LineEnd);
  EXPECT_EQ(round.at, 2u);  // thread 2, whose read ran thread 3
  Value order;
  ASSERT_TRUE(machine.read_global(static_cast<uint32_t>(image.find_global("order")), 0, order));
  // 1, then thread 2's digit, then thread 3's line inside thread 2's read, and no more.
  EXPECT_EQ(order.i, 123);
}

}  // namespace
}  // namespace uprog::test
