// Value ranges of int expressions, so that a product the compiler can prove to fit in int32 is a
// plain int (MULI) instead of Gold's promoting pair (MULID, manual 1.5). Conservative: anything
// not understood has the full int32 range.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include "dialects/gold/ast.h"

namespace uprog::gold {

struct IntRange {
  int64_t lo = INT32_MIN, hi = INT32_MAX;
};

// A `for` variable whose bounds are constants and whose body never assigns it: inside the body
// it stays within [lo, hi].
struct LoopRange {
  std::string_view name;
  IntRange range;
};

// The range of a checked int expression (types already filled in) given the enclosing loops;
// `depth` counts the levels already descended (past a limit the range is full).
IntRange range_of(const Expr& e, const std::vector<LoopRange>& loops, int depth = 0);

// Whether int * int of these checked operands always fits in int32.
bool product_fits(const Expr& a, const Expr& b, const std::vector<LoopRange>& loops);

// The range of `for name = start:step:end` over its body, when start, step and end are int
// constants; false otherwise (or when the step is zero).
bool constant_loop_range(const Stmt& for_loop, IntRange& out);

// Whether any statement of `b`, at any depth, assigns the variable `name` (=, [..] =, ++, --, for).
bool block_assigns(const Block& b, std::string_view name);

}  // namespace uprog::gold
