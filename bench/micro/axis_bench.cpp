// The simulated drive's servo cycle: Axis::step() on 1 and on 64 axes, each running relative
// moves back and forth with the motor on. items_per_second counts axis servo cycles.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "drive/axis.h"

namespace {

using uprog::drive::Axis;

void enable_and_move(Axis& axis, int32_t distance_counts) {
  axis.set_motor_on(true);
  for (uint32_t t = 0; t < uprog::drive::kEnableDelay_us + 5000; t += axis.period_us()) axis.step();
  axis.set_relative_move(distance_counts);
  axis.begin();
}

void BM_AxisStep(benchmark::State& state) {
  std::vector<Axis> axes(static_cast<size_t>(state.range(0)));
  int32_t distance = 20000;
  for (Axis& a : axes) enable_and_move(a, distance);
  for (auto _ : state) {
    for (Axis& a : axes) {
      benchmark::DoNotOptimize(a.step());
      if (!a.profiler_moving()) {
        distance = -distance;
        a.set_relative_move(distance);
        a.begin();
      }
    }
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["faults"] = static_cast<double>(axes.front().motor_fault());
}
BENCHMARK(BM_AxisStep)->Arg(1)->Arg(64);

}  // namespace
