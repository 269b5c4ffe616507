// The whole drive with the recorder recording 8 channels every servo cycle (7 axis signals and a
// program global) while a point-to-point program runs: what recording costs the servo cycle.
// Compare its rt_factor with BM_DriveProgram's (drive_bench.cpp); it must stay above 1000.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <string>

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

constexpr const char* kMoves = R"(int moves

function main()
    int k
    SP = 200000
    AC = 5000000
    DC = 5000000
    UM = 5
    MO = 1
    until (SO == 1)
    k = 0
    while (1)
        PA = 20000 * (1 - 2 * k)
        BG
        until (MS == 0)
        moves = moves + 1
        k = 1 - k
    end
return
)";

constexpr const char* kChannels[] = {"PX", "VX", "PE", "DV[3]", "DV[2]", "DV[1]", "IQ", "moves"};

bool arm(Controller& drive, std::string& why) {
  uprog::drive::RecorderSettings s;
  for (const char* name : kChannels) {
    std::optional<uprog::drive::Channel> c = drive.recorder_channel(name, &why);
    if (!c) return false;
    s.channels.push_back(*c);
  }
  s.length = static_cast<uint32_t>(uprog::drive::kMaxRecorderWords / s.channels.size());
  return drive.recorder().arm(s, &why);
}

void BM_DriveProgramRecording8(benchmark::State& state) {
  Controller drive(uprog::controller::ControllerOptions{&uprog::gold::dialect(), {}, false, {}});
  const uprog::gold::CompileResult compiled = uprog::gold::compile(uprog::SourceFile{"recorder_bench.ehl", kMoves});
  if (!compiled.ok() || !drive.download(uprog::bytecode::encode(compiled.image)).ok ||
      !drive.start_program("main").empty()) {
    state.SkipWithError("the program does not compile, download or start");
    return;
  }
  drive.advance(200'000);
  std::string why;
  if (!arm(drive, why)) {
    state.SkipWithError(why.c_str());
    return;
  }
  uint64_t samples = 0;
  double wall_s = 0;
  const uint64_t cycles_per_iteration = kVirtualPerIteration_us / drive.axis().period_us();
  for (auto _ : state) {
    if (drive.recorder().samples_recorded() + cycles_per_iteration + 1 > drive.recorder().settings().length) {
      state.PauseTiming();  // the recording would fill up in this second: take the memory again
      if (!arm(drive, why)) state.SkipWithError(why.c_str());
      state.ResumeTiming();
    }
    const uint32_t before = drive.recorder().samples_recorded();
    const auto start = std::chrono::steady_clock::now();
    drive.advance(kVirtualPerIteration_us);
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    samples += drive.recorder().samples_recorded() - before;
  }
  const double virtual_s = static_cast<double>(state.iterations()) * kVirtualPerIteration_us / 1e6;
  const double cycles = virtual_s * 1e6 / static_cast<double>(drive.axis().period_us());
  // Every servo cycle took a sample of every channel.
  if (static_cast<double>(samples) != cycles) state.SkipWithError("the recorder missed samples");
  state.counters["channels"] = static_cast<double>(std::size(kChannels));
  state.counters["samples_per_channel"] = static_cast<double>(samples);
  state.counters["cycles_per_s"] = benchmark::Counter(cycles, benchmark::Counter::kIsRate);
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  state.counters["rt_factor_wall"] = wall_s > 0 ? virtual_s / wall_s : 0;
}
BENCHMARK(BM_DriveProgramRecording8)->Unit(benchmark::kMillisecond);

}  // namespace
