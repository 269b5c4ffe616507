// The S300 drive in virtual time (the st dialect): a PLC62 of 20 lines, a PLC1 of 200 and a
// PLCMAIN that takes every line left (BM_StDrive), and the same without PLCMAIN
// (BM_StDriveRealTimeOnly), advanced 1 s of virtual time per iteration. Counters: the real-time
// factor (virtual s / CPU s) and the lines executed per CPU second.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "dialects/st/dialect.h"

namespace {

std::string st_program(bool with_main) {
  std::string s = "LONG A, B, C;\nPROGRAM PLC62\n";
  for (int i = 0; i < 20; ++i) s += "  A := A + 1;\n";
  s += "END_PROGRAM\nPROGRAM PLC1\n";
  for (int i = 0; i < 200; ++i) s += "  B := B + A;\n";
  s += "END_PROGRAM\n";
  if (with_main) s += "PROGRAM PLCMAIN\n  C := C + 1;\nEND_PROGRAM\n";
  return s;
}

// Real-time lines a virtual second: PLC62 20 × 16 000 runs, PLC1 200 × 1000 runs.
constexpr double kRealTimeLines = 20 * 16000 + 200 * 1000;

void run_drive(benchmark::State& state, bool with_main) {
  uprog::controller::ControllerOptions o;
  o.dialect = &uprog::st::dialect();
  uprog::controller::Controller drive(o);
  const std::string text = st_program(with_main);
  if (!drive.download(std::vector<uint8_t>(text.begin(), text.end())).ok ||
      !drive.query("PLCRUN").empty()) {
    state.SkipWithError("the program did not start");
    return;
  }
  for (auto _ : state) drive.advance(1'000'000);
  const double virtual_s = static_cast<double>(state.iterations());
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  // With PLCMAIN, it gets 6250 lines a ms less the real-time programs' 320 + 200: every line.
  const double lines = with_main ? 6.25e6 : kRealTimeLines;
  state.counters["lines_per_s"] =
      benchmark::Counter(virtual_s * lines, benchmark::Counter::kIsRate);
}

void BM_StDrive(benchmark::State& state) { run_drive(state, true); }
void BM_StDriveRealTimeOnly(benchmark::State& state) { run_drive(state, false); }
BENCHMARK(BM_StDrive)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StDriveRealTimeOnly)->Unit(benchmark::kMillisecond);

}  // namespace
