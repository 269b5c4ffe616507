// One count of a slice's Budget as the execute loop keeps it: a 32-bit register it decrements
// (a 64-bit one costs two registers and a carry on a 32-bit core) and the rest of the 64-bit
// budget, taken in chunks when the register runs out, off the hot path.
#pragma once
#include <cstdint>

namespace uprog::vm {

struct BudgetCount {
  uint32_t now;   // what the loop decrements
  uint64_t rest;  // what remains once `now` is spent

  // A budget count of 0 means no limit: 2^64 - 1 is never spent.
  static BudgetCount of(uint64_t budget) {
    const uint64_t total = budget != 0 ? budget : UINT64_MAX;
    const uint32_t first = total > UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(total);
    return {first, total - first};
  }
  // `now` is spent: takes the next chunk. False when the whole budget is spent.
  bool refill() {
    if (rest == 0) return false;
    now = rest > UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(rest);
    rest -= now;
    return true;
  }
  // Takes n from the budget: false when that spends it (then nothing is left).
  bool spend(uint32_t n) {
    while (n >= now) {
      n -= now;
      if (!refill()) {
        now = 0;
        return false;
      }
    }
    now -= n;
    return true;
  }
  // What is left of the whole budget.
  uint64_t left() const { return rest + now; }
};

}  // namespace uprog::vm
