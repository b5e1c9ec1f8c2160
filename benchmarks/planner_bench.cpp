// The planners' cost on the CPU, on the paper's display and on a 4K desktop
// side by side: the layer planner for n = 2..6 layers (the dynamic
// programme keeps every n well under a second on the 0.05-degree grid), and
// marwarp's mapping for a gaze off the principal point (paid on every frame
// whose gaze moved).
#include <benchmark/benchmark.h>

#include "foveate/core/acuity_warp.hpp"
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

void warp_mapping(benchmark::State& state, const char* display) {
  const foveate::Display d = foveate::Display::load(display);
  const foveate::AcuityWarp warp(d, foveate::AcuityModel::preset("A").finer(2.0));
  double x = 0.3 * d.width_px;
  for (auto _ : state) {
    // A new gaze each time, as an eye tracker's would be.
    x = x > 0.7 * d.width_px ? 0.3 * d.width_px : x + 1.0;
    benchmark::DoNotOptimize(warp.mapping({x, 0.4 * d.height_px}));
  }
}

}  // namespace

BENCHMARK_CAPTURE(plan, desktop_1080p, "desktop-1080p")
    ->DenseRange(2, 6)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plan, desktop_27_4k, "desktop-27-4k")
    ->DenseRange(2, 6)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(warp_mapping, desktop_1080p, "desktop-1080p")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(warp_mapping, desktop_27_4k, "desktop-27-4k")->Unit(benchmark::kMillisecond);
