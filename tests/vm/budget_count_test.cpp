// The execute loop's split of a 64-bit budget count into 32-bit chunks: the chunks add up to
// the budget exactly, and "no limit" is never spent; a count kept in units (the line count, in
// units of a word's line-end mark) counts the same.
#include "vm/budget_count.h"

#include <gtest/gtest.h>

namespace uprog::vm {
namespace {

// Spends a count to the end, one chunk at a time; returns the total it allowed.
uint64_t spend(BudgetCount c, int max_chunks) {
  uint64_t total = 0;
  for (int i = 0; i < max_chunks; ++i) {
    total += c.now;
    c.now = 0;
    if (!c.refill()) return total;
  }
  return UINT64_MAX;  // still not spent
}

TEST(BudgetCount, SmallBudgetsAreOneChunk) {
  const BudgetCount c = BudgetCount::of(13);
  EXPECT_EQ(c.now, 13u);
  EXPECT_EQ(c.rest, 0u);
  EXPECT_EQ(c.left(), 13u);
  BudgetCount spent = c;
  spent.now = 0;
  EXPECT_FALSE(spent.refill());
}

TEST(BudgetCount, LargeBudgetsAddUpExactly) {
  for (const uint64_t budget : {uint64_t{UINT32_MAX}, uint64_t{UINT32_MAX} + 1,
                                (uint64_t{1} << 33) + 7, uint64_t{3} * UINT32_MAX}) {
    const BudgetCount c = BudgetCount::of(budget);
    EXPECT_EQ(c.left(), budget);
    EXPECT_EQ(spend(c, 10), budget) << budget;
  }
}

TEST(BudgetCount, RefillKeepsWhatIsLeft) {
  BudgetCount c = BudgetCount::of(uint64_t{UINT32_MAX} + 5);
  c.now = 0;
  ASSERT_TRUE(c.refill());
  EXPECT_EQ(c.now, 5u);
  EXPECT_EQ(c.left(), 5u);
}

TEST(BudgetCount, NoLimitIsNeverSpent) {
  const BudgetCount c = BudgetCount::of(0);
  EXPECT_EQ(c.left(), UINT64_MAX);
  EXPECT_EQ(spend(c, 1000), UINT64_MAX);
}

// The line count: `now` in units of 256 (a word's line-end bit), so that a chunk holds at most
// 2^32 / 256 lines and the rest waits in `rest`, counted in lines.
using Lines = CountIn<256>;

TEST(LineCount, ChunksHoldWholeUnits) {
  const Lines c = Lines::of(13);
  EXPECT_EQ(c.now, 13u * 256u);
  EXPECT_EQ(c.left(), 13u);
  const Lines big = Lines::of(uint64_t{1} << 30);
  EXPECT_EQ(big.now, Lines::kChunk * 256u);
  EXPECT_EQ(big.rest, (uint64_t{1} << 30) - Lines::kChunk);
  EXPECT_EQ(big.left(), uint64_t{1} << 30);
}

TEST(LineCount, TakingOneAtATimeEndsAtTheBudget) {
  Lines c = Lines::of(3);
  EXPECT_FALSE(c.take_one());
  EXPECT_FALSE(c.take_one());
  EXPECT_TRUE(c.take_one());  // the third line was the last
  EXPECT_EQ(c.left(), 0u);
  EXPECT_FALSE(c.refill());
}

TEST(LineCount, SpendAcrossChunksLeavesTheRest) {
  Lines c = Lines::of(uint64_t{Lines::kChunk} + 10);
  EXPECT_TRUE(c.more_than(Lines::kChunk - 1));
  EXPECT_FALSE(c.more_than(Lines::kChunk));
  ASSERT_TRUE(c.spend(Lines::kChunk + 4));  // the first chunk and 4 of the next
  EXPECT_EQ(c.left(), 6u);
  EXPECT_EQ(c.now, 6u * 256u);
  EXPECT_FALSE(c.spend(6));  // spends the budget: nothing is left
  EXPECT_EQ(c.left(), 0u);
}

TEST(LineCount, NoLimitIsNeverSpent) {
  Lines c = Lines::of(0);
  EXPECT_EQ(c.left(), UINT64_MAX);
  EXPECT_TRUE(c.spend(UINT32_MAX));
  EXPECT_EQ(c.left(), UINT64_MAX - UINT32_MAX);
}

}  // namespace
}  // namespace uprog::vm
