// The whole drive with the recorder recording 8 channels every servo cycle while the axis makes
// point-to-point moves, commanded by a program (7 axis signals and a program global) or from
// the command line (8 axis signals): what recording costs the servo cycle. Compare the
// rt_factors with BM_DriveProgram's and BM_DriveIdle's (drive_bench.cpp).
#include <benchmark/benchmark.h>

#include <array>
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

// The program's run records one of its globals; the host's moves record the motion status.
constexpr std::array<const char*, 8> kProgramChannels = {"PX",    "VX",    "PE", "DV[3]",
                                                         "DV[2]", "DV[1]", "IQ", "moves"};
constexpr std::array<const char*, 8> kHostChannels = {"PX",    "VX",    "PE", "DV[3]",
                                                      "DV[2]", "DV[1]", "IQ", "MS"};
using ChannelNames = std::array<const char*, 8>;

bool arm(Controller& drive, const ChannelNames& names, std::string& why) {
  uprog::drive::RecorderSettings s;
  for (const char* name : names) {
    std::optional<uprog::drive::Channel> c = drive.recorder_channel(name, &why);
    if (!c) return false;
    s.channels.push_back(*c);
  }
  s.length = static_cast<uint32_t>(uprog::drive::kMaxRecorderWords / s.channels.size());
  return drive.recorder().arm(s, &why);
}

// Records every servo cycle while `one_second` moves the drive through a virtual second, and
// reports the real-time factor of the seconds alone (re-arming when the memory is full is not
// timed).
template <typename OneSecond>
void measure_recording(benchmark::State& state, Controller& drive, const ChannelNames& names,
                       OneSecond one_second) {
  std::string why;
  if (!arm(drive, names, why)) {
    state.SkipWithError(why.c_str());
    return;
  }
  uint64_t samples = 0;
  double wall_s = 0;
  const uint64_t cycles_per_iteration = kVirtualPerIteration_us / drive.axis().period_us();
  for (auto _ : state) {
    if (drive.recorder().samples_recorded() + cycles_per_iteration + 1 >
        drive.recorder().settings().length) {
      state.PauseTiming();  // the recording would fill up in this second: take the memory again
      if (!arm(drive, names, why)) state.SkipWithError(why.c_str());
      state.ResumeTiming();
    }
    const uint32_t before = drive.recorder().samples_recorded();
    const auto start = std::chrono::steady_clock::now();
    one_second();
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    samples += drive.recorder().samples_recorded() - before;
  }
  const double virtual_s = static_cast<double>(state.iterations()) * kVirtualPerIteration_us / 1e6;
  const double cycles = virtual_s * 1e6 / static_cast<double>(drive.axis().period_us());
  // Every servo cycle took a sample of every channel.
  if (static_cast<double>(samples) != cycles) state.SkipWithError("the recorder missed samples");
  state.counters["channels"] = static_cast<double>(names.size());
  state.counters["samples_per_channel"] = static_cast<double>(samples);
  state.counters["cycles_per_s"] = benchmark::Counter(cycles, benchmark::Counter::kIsRate);
  state.counters["rt_factor_cpu"] = benchmark::Counter(virtual_s, benchmark::Counter::kIsRate);
  state.counters["rt_factor_wall"] = wall_s > 0 ? virtual_s / wall_s : 0;
}

void BM_DriveProgramRecording8(benchmark::State& state) {
  Controller drive(uprog::controller::ControllerOptions{&uprog::gold::dialect(), {}, false, {}});
  const uprog::gold::CompileResult compiled =
      uprog::gold::compile(uprog::SourceFile{"recorder_bench.ehl", kMoves});
  if (!compiled.ok() || !drive.download(uprog::bytecode::encode(compiled.image)).ok ||
      !drive.start_program("main").empty()) {
    state.SkipWithError("the program does not compile, download or start");
    return;
  }
  drive.advance(200'000);
  measure_recording(state, drive, kProgramChannels,
                    [&] { drive.advance(kVirtualPerIteration_us); });
}
BENCHMARK(BM_DriveProgramRecording8)->Unit(benchmark::kMillisecond);

// The same moves commanded from the command line, no program: five a second, each PA and BG
// and 200 ms for the move (140 ms of profile) to settle.
void BM_DriveMovesRecording8(benchmark::State& state) {
  Controller drive(uprog::controller::ControllerOptions{&uprog::gold::dialect(), {}, false, {}});
  drive.set_lines_take_time(false);  // each second is exactly its servo cycles, all recorded
  for (const char* line : {"SP=200000", "AC=5000000", "DC=5000000", "UM=5", "MO=1"})
    drive.send(line);
  drive.advance(200'000);
  if (!drive.axis().servo_ready()) {
    state.SkipWithError("the servo is not ready 200 ms after MO=1");
    return;
  }
  bool forward = true;
  measure_recording(state, drive, kHostChannels, [&] {
    for (int move = 0; move < 5; ++move) {
      drive.send(forward ? "PA=10000" : "PA=-10000");
      drive.send("BG");
      drive.advance(kVirtualPerIteration_us / 5);
      forward = !forward;
    }
  });
  if (drive.axis().motion_status() != 0)
    state.SkipWithError("the last move did not settle in 200 ms");
}
BENCHMARK(BM_DriveMovesRecording8)->Unit(benchmark::kMillisecond);

}  // namespace
