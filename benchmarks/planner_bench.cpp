// The layer planner for n = 2..6 layers on the paper's display and on a 4K
// desktop, side by side: the dynamic programme keeps every n well under a
// second on the 0.05-degree grid.
#include <benchmark/benchmark.h>

#include "foveate/core/planner.hpp"

namespace {

void plan(benchmark::State& state, const char* display) {
  const foveate::Display d = foveate::Display::load(display);
  foveate::PlannerOptions o;
  o.layers = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(foveate::plan_layers(d, foveate::AcuityModel::preset("A"), o));
  }
}

}  // namespace

BENCHMARK_CAPTURE(plan, desktop_1080p, "desktop-1080p")
    ->DenseRange(2, 6)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plan, desktop_27_4k, "desktop-27-4k")
    ->DenseRange(2, 6)
    ->Unit(benchmark::kMillisecond);
