// One count of a slice's Budget as the execute loop keeps it: a 32-bit register it decrements
// (a 64-bit one costs two registers and a carry on a 32-bit core) and the rest of the 64-bit
// budget, taken in chunks when the register runs out, off the hot path.
#pragma once
#include <cstdint>

namespace uprog::vm {

// `now` holds the chunk in units of kUnit: the line count's unit is a word's line-end bit, so
// that every dispatch takes its line as `now -= word & kLineEndBit`, without a shift or a
// branch on the mark (docs/architecture.md, "Scheduling": the line-end mark).
template <uint32_t kUnit>
struct CountIn {
  uint32_t now;   // what the loop decrements, kUnit for each count
  uint64_t rest;  // the counts that remain once `now` is spent

  static constexpr uint32_t kChunk = UINT32_MAX / kUnit;  // the counts `now` can hold

  // A budget count of 0 means no limit: 2^64 - 1 is never spent.
  static CountIn of(uint64_t budget) {
    const uint64_t total = budget != 0 ? budget : UINT64_MAX;
    const uint32_t first = total > kChunk ? kChunk : static_cast<uint32_t>(total);
    return {first * kUnit, total - first};
  }
  // `now` is spent: takes the next chunk. False when the whole budget is spent.
  bool refill() {
    if (rest == 0) return false;
    const uint32_t next = rest > kChunk ? kChunk : static_cast<uint32_t>(rest);
    now = next * kUnit;
    rest -= next;
    return true;
  }
  // Takes n counts from the budget: false when that spends it (then nothing is left).
  bool spend(uint32_t n) {
    while (n >= now / kUnit) {
      n -= now / kUnit;
      if (!refill()) {
        now = 0;
        return false;
      }
    }
    now -= n * kUnit;
    return true;
  }
  // Takes one count: true when it was the last of `now` (the loop then refills or stops).
  bool take_one() { return (now -= kUnit) == 0; }
  // More than n counts are left in `now`.
  bool more_than(uint32_t n) const { return now > uint64_t{n} * kUnit; }
  // What is left of the whole budget.
  uint64_t left() const { return rest + now / kUnit; }
};

using BudgetCount = CountIn<1>;

}  // namespace uprog::vm
