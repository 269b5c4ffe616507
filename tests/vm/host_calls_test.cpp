// The Host contract seen from a program: which thread a message comes from, a refused message
// or command (no effect, the drive's code kept), a call that ends the slice, and a host that
// shows no messages.
#include <gtest/gtest.h>

#include "vm_fixture.h"

namespace uprog::test {
namespace {

using vm::Budget;
using vm::RunError;
using vm::SliceEnd;

const char* kTwoMessages = R"(
.global int "after" 1
.text "first %d"
.text "second"
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 11
  MSG 0 1
  MSG 1 0
  PUSHI 1
  STG after
  RET
)";

TEST(HostCalls, AMessageNamesItsThread) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kTwoMessages));
  ASSERT_EQ(p.machine.start(2, 0), RunError::None);
  EXPECT_EQ(p.run_to_end(2).end, SliceEnd::Finished);
  ASSERT_EQ(p.host.message_count, 2u);
  EXPECT_EQ(p.host.messages[0].thread, 2u);
  EXPECT_EQ(p.host.messages[0].arguments(), std::vector<int32_t>{11});
  EXPECT_STREQ(p.machine.image().text(p.host.messages[0].text), "first %d");
  EXPECT_STREQ(p.machine.image().text(p.host.messages[1].text), "second");
}

TEST(HostCalls, ARefusedMessageStopsTheThreadBeforeItsEffect) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kTwoMessages));
  p.host.message_status = 21;
  p.machine.start(0, 0);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Error);
  EXPECT_EQ(p.machine.last_error(0), RunError::CommandRefused);
  EXPECT_EQ(p.machine.error_detail(0), 21);
  EXPECT_EQ(p.machine.pc(0), 1u);  // still at the MSG
  EXPECT_EQ(p.global("after").i, 0);
}

TEST(HostCalls, AMessageCanEndTheSlice) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(kTwoMessages));
  p.host.message_status = vm::kCommandEndSlice;
  p.machine.start(0, 0);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Yielded);
  EXPECT_EQ(p.host.message_count, 1u);
  EXPECT_EQ(p.machine.pc(0), 3u);  // after the first MSG, its value popped
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Yielded);
  EXPECT_EQ(p.host.message_count, 2u);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Finished);
  EXPECT_EQ(p.global("after").i, 1);
  EXPECT_EQ(p.machine.last_error(0), RunError::None);
}

TEST(HostCalls, AnEndedSliceCountsItsInstruction) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  CMDSET 4 0
  RET
)"));
  p.machine.start(0, 0);
  const vm::SliceResult r = p.machine.run_slice(0, Budget::of_instructions(10));
  EXPECT_EQ(r.end, SliceEnd::Yielded);
  EXPECT_EQ(r.executed, 2u);
  EXPECT_EQ(p.machine.pc(0), 3u);
}

// A host that has drive commands and a clock, and no way to show a message.
class SilentHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t, int32_t, Value&) override { return vm::kCommandOk; }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return vm::kCommandOk; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override {
    return vm::kCommandOk;
  }
  uint32_t now_us() override { return 0; }
};

TEST(HostCalls, AHostWithoutMessagesRefusesThem) {
  bytecode::Image image;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(bytecode::assemble(kTwoMessages, "t.s", image, errors)) << format_text(errors);
  const std::vector<uint8_t> bytes = bytecode::encode(image);
  bytecode::ImageView view;
  ASSERT_EQ(bytecode::load_image(bytes.data(), bytes.size(), view), bytecode::LoadError::Ok);
  std::vector<uint64_t> memory(vm::Machine::memory_needed(view, {}) / 8 + 1);
  SilentHost host;
  vm::Machine machine;
  ASSERT_TRUE(
      machine.load(bytes.data(), bytes.size(), {}, memory.data(), memory.size() * 8, host).ok());
  machine.start(0, 0);
  EXPECT_EQ(machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Error);
  EXPECT_EQ(machine.last_error(0), RunError::CommandRefused);
  EXPECT_EQ(machine.error_detail(0), vm::kCommandUnsupported);
}

TEST(HostCalls, ARefusedIndexedActionKeepsItsOperands) {
  LoadedProgram p;
  ASSERT_TRUE(p.load(R"(
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  PUSHI 6
  CMDRUNX 2 1
  RET
)"));
  p.machine.start(0, 0);
  EXPECT_EQ(p.machine.run_slice(0, Budget::unlimited()).end, SliceEnd::Error);
  EXPECT_EQ(p.machine.error_detail(0), 21);
  EXPECT_EQ(p.machine.pc(0), 2u);
  EXPECT_EQ(p.host.runs, 0);
}

}  // namespace
}  // namespace uprog::test
