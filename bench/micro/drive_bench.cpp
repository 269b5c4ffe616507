// The whole simulated drive in virtual time: a Controller (set up as `uprog run` does) with one
// axis, advanced 1 s of virtual time per iteration at the default budget (one source line per
// servo cycle). BM_DriveProgram runs a point-to-point motion program; BM_DriveIdle has none.
// Counters: servo cycles per second and the real-time factor (virtual s / CPU s, and / wall s).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "controller/controller.h"
#include "dialects/gold/compile.h"
#include "dialects/gold/dialect.h"
#include "drive/axis.h"
#include "support/diagnostic.h"
#include "support/source.h"

namespace {

using uprog::controller::Controller;

constexpr uint64_t kVirtualPerIteration_us = 1'000'000;

// A typical drive program: motor on in position mode, then moves back and forth forever, each
// waited for with `until (MS == 0)`, with some arithmetic on every move.
constexpr const char* kMotionProgram = R"(int moves, target, checksum
float gain, scaled

function main()
    int k
    SP = 200000
    AC = 5000000
    DC = 5000000
    MO = 0
    UM = 5
    MO = 1
    until (SO == 1)
    k = 0
    gain = 1.5
    while (1)
        target = 20000 * (1 - 2 * k) + moves % 7
        PA = target
        BG
        until (MS == 0)
        scaled = gain * PX + 3.25
        checksum = checksum + (moves * 7) % 13
        moves = moves + 1
        k = 1 - k
    end
return
)";

int32_t query_int(Controller& drive, const char* name) {
  const std::vector<uprog::controller::Answer> a = drive.query(name);
  return a.size() == 1 && !a[0].is_error() ? std::atoi(a[0].text.c_str()) : -1;
}

uprog::controller::ControllerOptions gold_drive() {
  uprog::controller::ControllerOptions o;
  o.dialect = &uprog::gold::dialect();
  return o;
}

void report(benchmark::State& state, double wall_s, Controller& drive) {
  const double virtual_s = static_cast<double>(state.iterations()) * kVirtualPerIteration_us / 1e6;
  const double cycles = virtual_s * 1e6 / static_cast<double>(drive.axis().period_us());
  state.counters["cycles_per_s"] = benchmark::Counter(cycles, benchmark::Counter::kIsRate);
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  state.counters["rt_factor_wall"] = wall_s > 0 ? virtual_s / wall_s : 0;
}

void BM_DriveProgram(benchmark::State& state) {
  Controller drive(gold_drive());  // no state dir, one line per background pass
  const uprog::gold::CompileResult compiled =
      uprog::gold::compile(uprog::SourceFile{"drive_bench.ehl", kMotionProgram});
  if (!compiled.ok()) {
    state.SkipWithError(uprog::format_text(compiled.diagnostics).c_str());
    return;
  }
  if (!drive.download(uprog::bytecode::encode(compiled.image)).ok ||
      !drive.start_program("main").empty()) {
    state.SkipWithError("the program does not download or start");
    return;
  }
  drive.advance(200'000);  // enable delay and the first move under way
  if (!drive.program_running() || !drive.axis().motor_on()) {
    state.SkipWithError("the program is not running with the motor on after 200 ms");
    return;
  }
  const int32_t moves_before = query_int(drive, "moves");
  int32_t position = drive.axis().position();
  int64_t travel_counts = 0;
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    drive.advance(kVirtualPerIteration_us);
    const int32_t now = drive.axis().position();
    travel_counts += now > position ? now - position : position - now;
    if (!drive.program_running() || drive.axis().motor_fault() != 0 || now == position) {
      state.SkipWithError("the program stopped, the drive faulted, or the axis did not move");
      break;
    }
    position = now;
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const int32_t moves = query_int(drive, "moves") - moves_before;
  // Each move of 40 000 counts takes well under 1 s: fewer moves than seconds means a stall.
  if (moves < static_cast<int64_t>(state.iterations())) {
    state.SkipWithError("the program made fewer moves than one per virtual second");
  }
  report(state, wall_s, drive);
  state.counters["moves_per_virtual_s"] =
      static_cast<double>(moves) / static_cast<double>(state.iterations());
  state.counters["travel_counts"] = static_cast<double>(travel_counts);
}
BENCHMARK(BM_DriveProgram)->Unit(benchmark::kMillisecond);

// The same drive with no program: the motor on, holding position (servo cycles only).
void BM_DriveIdle(benchmark::State& state) {
  Controller drive(gold_drive());
  drive.send("UM=5");
  drive.send("MO=1");
  drive.advance(100'000);
  if (!drive.axis().motor_on() || query_int(drive, "PS") != -2) {
    state.SkipWithError("the motor did not come on, or a program is loaded");
    return;
  }
  const auto wall_start = std::chrono::steady_clock::now();
  for (auto _ : state) drive.advance(kVirtualPerIteration_us);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  report(state, wall_s, drive);
}
BENCHMARK(BM_DriveIdle)->Unit(benchmark::kMillisecond);

}  // namespace
