// native: the reference. Every pixel shaded once, at the display's sampling.
#include "../registry/registry.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

class Native final : public Technique {
 public:
  FrameStats render(Scene& scene, const FrameInput&, const GazeState&,
                    const gpu::RenderTarget& target) override {
    const View view = View::full(target.width(), target.height());
    scene.prepass(view);
    const PixelCount n =
        kit_.shade(scene, view, kMapRect, target,
                   [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); });
    return one_pass_stats("screen", n.read(), target.width(), target.height());
  }

  std::vector<OverlayShape> overlay(const GazeState& g) const override { return {gaze_dot(g)}; }

 private:
  PassKit kit_;
};

}  // namespace

TechniqueInfo native_info() {
  TechniqueInfo t;
  t.name = "native";
  t.summary = "Non-foveated reference: every pixel shaded at the display's resolution.";
  t.source = "-";
  t.make = [](const TechniqueConfig&, const ParamValues&) { return std::make_unique<Native>(); };
  return t;
}

}  // namespace foveate::tech
