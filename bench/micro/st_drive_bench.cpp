// The S300 drive in virtual time (the st dialect): a PLC62 of 20 lines, a PLC1 of 200 and a
// PLCMAIN that takes every line left, advanced 1 s of virtual time per iteration. Counter:
// the real-time factor (virtual s / CPU s) and the lines executed per CPU second.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "dialects/st/dialect.h"

namespace {

std::string st_program() {
  std::string s = "LONG A, B, C;\nPROGRAM PLC62\n";
  for (int i = 0; i < 20; ++i) s += "  A := A + 1;\n";
  s += "END_PROGRAM\nPROGRAM PLC1\n";
  for (int i = 0; i < 200; ++i) s += "  B := B + A;\n";
  s += "END_PROGRAM\nPROGRAM PLCMAIN\n  C := C + 1;\nEND_PROGRAM\n";
  return s;
}

void BM_StDrive(benchmark::State& state) {
  uprog::controller::ControllerOptions o;
  o.dialect = &uprog::st::dialect();
  uprog::controller::Controller drive(o);
  const std::string text = st_program();
  if (!drive.download(std::vector<uint8_t>(text.begin(), text.end())).ok || !drive.query("PLCRUN").empty()) {
    state.SkipWithError("the program did not start");
    return;
  }
  for (auto _ : state) drive.advance(1'000'000);
  const double virtual_s = static_cast<double>(state.iterations());
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  // PLCMAIN gets 6250 lines a ms less the real-time programs' 320 + 200: every line of the CPU.
  state.counters["lines_per_s"] = benchmark::Counter(virtual_s * 6.25e6, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StDrive)->Unit(benchmark::kMillisecond);

}  // namespace
