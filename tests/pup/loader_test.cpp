// The CUP loader refuses what the spec forbids, by CUP line ("line N: why"), and translates the
// rest into an image the verifier accepts, with a line-table entry per CUP line.
#include <gtest/gtest.h>

#include "bytecode/image_view.h"
#include "bytecode/verifier.h"
#include "dialects/pup/cup_loader.h"

namespace uprog::pup {
namespace {

bool verifies(const LoadedCup& loaded) {
  const std::vector<uint8_t> bytes = bytecode::encode(loaded.image);
  bytecode::ImageView view;
  if (bytecode::load_image(bytes.data(), bytes.size(), view) != bytecode::LoadError::Ok)
    return false;
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(view) / 4 + 1);
  return bytecode::verify(view, bytecode::VerifyLimits{}, scratch.data(), scratch.size() * 4).ok();
}

std::string refusal(std::vector<std::string> lines, std::vector<CupEvent> events = {}) {
  CupProgram p;
  p.name = "t";
  p.lines = std::move(lines);
  p.events = std::move(events);
  std::string why;
  EXPECT_FALSE(load_cup(p, &why).has_value());
  return why;
}

TEST(CupLoader, RefusesUnsafeLinesByTheirNumber) {
  // Line 2 is reached with 0 (the task's start) and with 1 (the jump back from line 3).
  EXPECT_EQ(refusal({"AProgTask[1]", "APushConstant,1", "AJump[1],2"}),
            "line 2: reachable at two stack depths");
  EXPECT_EQ(refusal({"AProgFunc[1]", "APushConstant,1", "AReturn"}),
            "line 3: AReturn with values on the stack");
  EXPECT_EQ(refusal({"AProgTask[1]", "ASpeed"}), "line 2: a bare read of 'ASpeed'");
  EXPECT_EQ(refusal({"AProgTask[1]", "ANoSuch=1"}), "line 2: unknown keyword 'ANoSuch'");
  EXPECT_EQ(refusal({"ASpeed = 5"}), "line 1: blanks in a program line");
  EXPECT_EQ(refusal({"AJump[1],3"}), "line 1: jump to line 3, which is not there");
  EXPECT_EQ(refusal({"AProgFuncCall,2"}), "line 1: no function 2");
  EXPECT_EQ(refusal({"ADownloadUProg[1],5"}),
            "line 1: 'ADownloadUProg' is not allowed in a program (error 14)");
  EXPECT_EQ(refusal({"AVel=5"}), "line 1: 'AVel' is not assignable");
  EXPECT_EQ(refusal({"AMath[16]"}), "line 1: no AMath[16]");
  EXPECT_EQ(refusal({"AGenData[0]=1"}), "line 1: index 0 of 'AGenData' out of range");
  EXPECT_EQ(refusal({"APopParam,ATime"}), "line 1: 'ATime' is read only");
  EXPECT_EQ(refusal({"AProgTask[1]", "AProgTask[1]"}), "line 2: defined twice");
  EXPECT_EQ(refusal({"AWaitTime"}), "line 1: 'AWaitTime' needs an argument");
  EXPECT_EQ(refusal({""}), "line 1: empty line");
  EXPECT_EQ(refusal({"AProgTask[1]"}, {{6, 1}}), "line 0: event 6: no function 1");
}

TEST(CupLoader, EveryLineHasItsCodeAndTheImageVerifies) {
  CupProgram p;
  p.name = "Counter";
  p.lines = {"AProgTask[1]", "AWaitTime,1000",         "AJump[1],2",
             "AProgFunc[1]", "APushParam,AGenData[1]", "APushConstant,1",
             "AMath[1]",     "APopParam,AGenData[1]",  "AReturn"};
  p.events = {{6, 1}};
  std::string why;
  const auto loaded = load_cup(p, &why);
  ASSERT_TRUE(loaded) << why;
  EXPECT_EQ(loaded->image.lines.size(), 9u);
  for (uint32_t l = 1; l <= 9; ++l) EXPECT_EQ(loaded->image.lines[l - 1].line, l);
  EXPECT_EQ(loaded->line_of(loaded->line_pc[5]), 5u);
  EXPECT_EQ(loaded->line_depth[6], 1);  // after APushParam
  EXPECT_EQ(loaded->line_depth[7], 2);
  EXPECT_GE(loaded->task_routine[1], 0);
  EXPECT_LT(loaded->task_routine[2], 0);
  EXPECT_GE(loaded->event_routine[6], 0);
  EXPECT_TRUE(verifies(*loaded));
}

// The manual: the controller "generate[s] errors if trying to push into a full expressions stack
// or trying to pop from an empty stack ... Such error will halt the user program": a run-time
// error of the line (tests/transcripts/pup/stack_errors_at_run_time.txt runs them), not a refusal.
TEST(CupLoader, AStackErrorOfHandWrittenCupLoadsAndFailsOnItsLine) {
  std::vector<std::string> deep = {"AProgTask[1]"};
  for (int i = 0; i < 51; ++i) deep.push_back("APushConstant,1");
  // Line 3 is also reached from line 6 with one entry: the failing line 2 does not go on to it.
  const std::vector<std::string> joined = {"AProgTask[1]",          "APopParam,AGenData[1]",
                                           "APopParam,AGenData[2]", "AProgTask[2]",
                                           "APushConstant,1",       "AJump[1],3"};
  for (const auto& lines : {std::vector<std::string>{"AProgTask[1]", "APopParam,AGenData[1]"},
                            std::vector<std::string>{"AProgTask[1]", "AMath[1]"}, deep, joined}) {
    CupProgram p;
    p.name = "t";
    p.lines = lines;
    std::string why;
    const auto loaded = load_cup(p, &why);
    ASSERT_TRUE(loaded) << why;
    EXPECT_TRUE(verifies(*loaded));
  }
}

}  // namespace
}  // namespace uprog::pup
