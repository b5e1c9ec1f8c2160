// Plans the paper's three layers for the paper's display and prints them.
#include <cstdio>

#include "foveate/core/planner.hpp"

int main() {
  const foveate::LayerPlan plan = foveate::plan_layers(foveate::Display::load("desktop-1080p"),
                                                       foveate::AcuityModel::preset("A"));
  for (const foveate::Layer& layer : plan.layers) {
    std::printf("layer: %.2f deg, s = %.2f, %dx%d\n", layer.radius_deg, layer.sampling_factor,
                layer.width_px, layer.height_px);
  }
  std::printf("pixel ratio (half rate): %.1fx\n", plan.pixel_ratio_half_rate());
  return plan.pixel_ratio_half_rate() > 10.0 ? 0 : 1;
}
