// The CUP loader refuses what the spec forbids, by CUP line ("line N: why"), and translates the
// rest into an image the verifier accepts, with a line-table entry per CUP line.
#include <gtest/gtest.h>

#include "bytecode/image_view.h"
#include "bytecode/verifier.h"
#include "dialects/pup/cup_loader.h"

namespace uprog::pup {
namespace {

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
  EXPECT_EQ(refusal({"AProgTask[1]", "APopParam,AGenData[1]"}), "line 2: a pop that may find the stack empty");
  EXPECT_EQ(refusal({"AProgTask[1]", "AMath[1]"}), "line 2: a pop that may find the stack empty");
  // Line 2 is reached with 0 (the task's start) and with 1 (the jump back from line 3).
  EXPECT_EQ(refusal({"AProgTask[1]", "APushConstant,1", "AJump[1],2"}), "line 2: reachable at two stack depths");
  std::vector<std::string> deep = {"AProgTask[1]"};
  for (int i = 0; i < 51; ++i) deep.push_back("APushConstant,1");
  EXPECT_EQ(refusal(deep), "line 52: the expression stack would pass 50");
  EXPECT_EQ(refusal({"AProgFunc[1]", "APushConstant,1", "AReturn"}), "line 3: AReturn with values on the stack");
  EXPECT_EQ(refusal({"AProgTask[1]", "ASpeed"}), "line 2: a bare read of 'ASpeed'");
  EXPECT_EQ(refusal({"AProgTask[1]", "ANoSuch=1"}), "line 2: unknown keyword 'ANoSuch'");
  EXPECT_EQ(refusal({"ASpeed = 5"}), "line 1: blanks in a program line");
  EXPECT_EQ(refusal({"AJump[1],3"}), "line 1: jump to line 3, which is not there");
  EXPECT_EQ(refusal({"AProgFuncCall,2"}), "line 1: no function 2");
  EXPECT_EQ(refusal({"ADownloadUProg[1],5"}), "line 1: 'ADownloadUProg' is not allowed in a program (error 14)");
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
  p.lines = {"AProgTask[1]", "AWaitTime,1000", "AJump[1],2", "AProgFunc[1]", "APushParam,AGenData[1]",
             "APushConstant,1", "AMath[1]", "APopParam,AGenData[1]", "AReturn"};
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
  const std::vector<uint8_t> bytes = bytecode::encode(loaded->image);
  bytecode::ImageView view;
  ASSERT_EQ(bytecode::load_image(bytes.data(), bytes.size(), view), bytecode::LoadError::Ok);
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(view) / 4 + 1);
  EXPECT_TRUE(bytecode::verify(view, bytecode::VerifyLimits{}, scratch.data(), scratch.size() * 4).ok());
}

}  // namespace
}  // namespace uprog::pup
