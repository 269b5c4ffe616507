// The execute loop's split of a 64-bit budget count into 32-bit chunks: the chunks add up to
// the budget exactly, and "no limit" is never spent.
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

}  // namespace
}  // namespace uprog::vm
