// VM micro-benchmarks: dispatch (assembly loops), calls and array access (Gold programs).
// items_per_second counts executed VM instructions.
#include <benchmark/benchmark.h>

#include <string>

#include "program.h"

namespace {

using uprog::bench::Program;

void run(benchmark::State& state, Program& program) {
  const uint64_t per_run = program.count_main();
  if (per_run == 0) {
    state.SkipWithError("the program did not finish");
    return;
  }
  for (auto _ : state) {
    if (!program.run_main()) {
      state.SkipWithError("the program did not finish");
      return;
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(per_run * state.iterations()));
}

void load_assembly(benchmark::State& state, Program& program, const std::string& text) {
  const std::string error = program.load_assembly(text);
  if (!error.empty()) state.SkipWithError(error.c_str());
}
void load_gold(benchmark::State& state, Program& program, const std::string& text) {
  const std::string error = program.load_gold(text);
  if (!error.empty()) state.SkipWithError(error.c_str());
}

// A counting loop: INCL, LDL, PUSHI, CMPI, JNZ per iteration (5 dispatches).
void BM_DispatchLoop(benchmark::State& state) {
  Program p;
  load_assembly(state, p, R"(.routine function "main" in=0 out=0 entry=main
.local int "i"
main:
  PUSHI 0
  STL 0
loop:
  INCL 0 1
  LDL 0
  PUSHI 100000
  CMPI 2
  JNZ loop
  RET
)");
  run(state, p);
}
BENCHMARK(BM_DispatchLoop);

// Straight-line dispatch: 16 NOPs per iteration of the same loop.
void BM_DispatchNop(benchmark::State& state) {
  std::string nops;
  for (int i = 0; i < 16; ++i) nops += "  NOP\n";
  Program p;
  load_assembly(state, p, R"(.routine function "main" in=0 out=0 entry=main
.local int "i"
main:
  PUSHI 0
  STL 0
loop:
)" + nops + R"(  INCL 0 1
  LDL 0
  PUSHI 10000
  CMPI 2
  JNZ loop
  RET
)");
  run(state, p);
}
BENCHMARK(BM_DispatchNop);

// The same counting loop as the Gold compiler emits it (for, EOLs and all).
void BM_GoldForLoop(benchmark::State& state) {
  Program p;
  load_gold(state, p, R"(int result
function main()
global int result
int i, s
s = 0
for i = 1:100000
  s = s + i
end
result = s
return
)");
  run(state, p);
}
BENCHMARK(BM_GoldForLoop);

// 100000 calls of a one-input, one-output function.
void BM_GoldCall(benchmark::State& state) {
  Program p;
  load_gold(state, p, R"(int result
function main()
global int result
int i, s
s = 0
for i = 1:100000
  s = s + inc(i)
end
result = s
return

function [int r] = inc(int x)
r = x + 1
return
)");
  run(state, p);
}
BENCHMARK(BM_GoldCall);

// The same calls in assembly, without the EOLs and for-loop code Gold adds.
void BM_AsmCall(benchmark::State& state) {
  Program p;
  load_assembly(state, p, R"(.routine function "main" in=0 out=0 entry=main
.local int "i"
.routine function "inc" in=1 out=1 entry=inc
.local int "x"
.local int "r"
main:
  PUSHI 0
  STL 0
loop:
  LDL 0
  CALL inc 1
  POP
  INCL 0 1
  LDL 0
  PUSHI 100000
  CMPI 2
  JNZ loop
  RET
inc:
  LDL 0
  PUSHI 1
  ADDI
  STL 1
  RET
)");
  run(state, p);
}
BENCHMARK(BM_AsmCall);

// Writes, then reads, of a 2000-element global int array (2040 words is Gold's whole data
// segment, and the read needs one more global for its result).
void BM_GoldArrayWrite(benchmark::State& state) {
  Program p;
  load_gold(state, p, R"(int a[2000]
function main()
global int a[2000]
int i
for i = 0:1999
  a[i] = i
end
return
)");
  run(state, p);
}
BENCHMARK(BM_GoldArrayWrite);

void BM_GoldArrayRead(benchmark::State& state) {
  Program p;
  load_gold(state, p, R"(int a[2000]
int result
function main()
global int a[2000]
global int result
int i, s
s = 0
for i = 0:1999
  s = s + a[i]
end
result = s
return
)");
  run(state, p);
}
BENCHMARK(BM_GoldArrayRead);

}  // namespace
