// native: the reference. Every pixel shaded once, at the display's sampling.
#include "../common/kit.hpp"
#include "../common/registry.hpp"

namespace foveate::tech {

namespace {

class Native final : public Technique {
 public:
  explicit Native(const TechniqueConfig& c) : display_(c.display) {
    Params p("native", c);
    p.finish();
  }
  std::string name() const override { return "native"; }
  std::vector<std::pair<std::string, double>> parameters() const override { return {}; }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState&,
                    GLuint target) override {
    const View view = View::full(frame.width, frame.height);
    scene.prepass(view);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, frame.width, frame.height);
    const double n = kit_.shade(scene, view, kMapRect,
                                [&](const gpu::Program& p) { set_rect_mapping(p, view); });
    return one_pass_stats("screen", n, frame.width, frame.height);
  }

  std::vector<OverlayShape> overlay(const GazeState& g) const override {
    return {{OverlayShape::Kind::Dot, g.gaze_px.x, g.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f}};
  }

 private:
  Display display_;
  Kit kit_;
};

}  // namespace

TechniqueInfo native_info() {
  return {"native",
          "Non-foveated reference: every pixel shaded at the display's resolution.",
          "-",
          {},
          [](const TechniqueConfig& c) { return std::make_unique<Native>(c); },
          [](const TechniqueConfig&) { return std::vector<std::pair<std::string, double>>{}; }};
}

}  // namespace foveate::tech
