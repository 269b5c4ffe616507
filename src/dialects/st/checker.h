// The checks that need the whole file: built-ins' arguments, FUNCTION calls (unknown,
// recursion), the placement rules through called functions (16, 17, 18), and each program's
// size and the load factor (32).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dialects/st/ast.h"
#include "dialects/st/reporter.h"

namespace uprog::st {

struct ProgramSize {
  ProgramKind kind;
  std::string name;
  uint32_t size = 0;
};

struct CheckResult {
  std::vector<ProgramSize> sizes;  // the programs present, in the report's order
  uint64_t load = 0;
};

constexpr uint64_t kMaxLoad = 100'000;

CheckResult check(const Program& program, Reporter& reporter);

// The conversions of a PRINTF format (%d %u %x %X with -, 0 and a width; %% a percent sign),
// or -1 when it has another one.
int format_conversions(const std::string& format);

}  // namespace uprog::st
