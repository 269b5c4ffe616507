// The AG300 drive in virtual time (the pup dialect): all eight threads busy, each one CUP line
// a 50 us cycle (bench/pup/eight_threads.pup), against the same drive with its program idle
// (bench/pup/idle.pup), advanced 1 s of virtual time per iteration. Counters: the real-time
// factor (virtual s / CPU s) and the CUP lines executed per CPU second.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "controller/controller.h"
#include "dialects/pup/dialect.h"
#include "support/diagnostic.h"

namespace {

void run_drive(benchmark::State& state, const char* file, double lines_per_virtual_s) {
  uprog::controller::ControllerOptions o;
  o.dialect = &uprog::pup::dialect();
  uprog::controller::Controller drive(o);
  std::vector<uprog::Diagnostic> diagnostics;
  if (!drive.download_source_file(std::string(UPROG_SOURCE_DIR) + "/bench/pup/" + file,
                                  diagnostics) ||
      !drive.start_program().empty()) {
    state.SkipWithError("the program did not download or start");
    return;
  }
  drive.advance(10'000);
  for (auto _ : state) drive.advance(1'000'000);
  const double virtual_s = static_cast<double>(state.iterations());
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  state.counters["lines_per_s"] =
      benchmark::Counter(virtual_s * lines_per_virtual_s, benchmark::Counter::kIsRate);
}

// Eight threads, one line each in each of 20 000 cycles a virtual second.
void BM_PupDriveEightThreads(benchmark::State& state) {
  run_drive(state, "eight_threads.pup", 8 * 20'000);
}
void BM_PupDriveIdle(benchmark::State& state) { run_drive(state, "idle.pup", 0); }
BENCHMARK(BM_PupDriveEightThreads)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PupDriveIdle)->Unit(benchmark::kMillisecond);

}  // namespace
