// The HIWIN drive in virtual time (the pdl dialect): three tasks running, one command of one
// task per 50 us phase (two count, the third adds under lock), advanced 1 s of virtual time per
// iteration. Compare its rt_factor_cpu with BM_DriveProgram's in the same run.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "controller/controller.h"
#include "dialects/pdl/compile.h"
#include "dialects/pdl/dialect.h"
#include "support/diagnostic.h"
#include "support/source.h"

namespace {

// In the drive's grammar: one operator an assignment (manual 2.1).
constexpr const char* kThreeTasks = R"(#long a, b, c, shared, r7
#task/1;
while (1) do
  a++;
end;
#task/2;
while (1) do
  r7=a%7;
  b+=r7;
end;
#task/3;
while (1) do
  lock;
  c=shared;
  shared=c+1;
  unlock;
end;
)";

int32_t query_int(uprog::controller::Controller& drive, const char* name) {
  const std::vector<uprog::controller::Answer> a = drive.query(name);
  return a.size() == 1 && !a[0].is_error() ? std::atoi(a[0].text.c_str()) : -1;
}

void BM_PdlDriveThreeTasks(benchmark::State& state) {
  uprog::controller::ControllerOptions o;
  o.dialect = &uprog::pdl::dialect();
  uprog::controller::Controller drive(o);
  const uprog::pdl::CompileResult compiled =
      uprog::pdl::compile(uprog::SourceFile{"three_tasks.pdl", kThreeTasks});
  if (!compiled.ok()) {
    state.SkipWithError(uprog::format_text(compiled.diagnostics).c_str());
    return;
  }
  if (!drive.download(uprog::bytecode::encode(compiled.image)).ok ||
      !drive.start_program().empty()) {
    state.SkipWithError("the program does not download or start");
    return;
  }
  drive.advance(10'000);
  for (auto _ : state) drive.advance(1'000'000);
  // Every task had its turns: none stalled.
  if (query_int(drive, "a") <= 0 || query_int(drive, "b") <= 0 || query_int(drive, "shared") <= 0) {
    state.SkipWithError("a task did not run");
  }
  const double virtual_s = static_cast<double>(state.iterations());
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  state.counters["phases_per_s"] =
      benchmark::Counter(virtual_s * 20'000, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PdlDriveThreeTasks)->Unit(benchmark::kMillisecond);

}  // namespace
