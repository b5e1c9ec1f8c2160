#pragma once
// A technique written outside the library with its public API only, as a
// user would: it renders the scene with native, then blacks out `bar_px`
// rows at the top and the bottom. Its one parameter is declared with a
// default derived from the display (a 36th of the height). Registered at run
// time by the tests that use it (register_bars_technique()).
#include "foveate/core/error.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate::test {

inline constexpr const char* kBarsTechnique = "test-bars";

class BarsTechnique final : public Technique {
 public:
  BarsTechnique(const TechniqueConfig& c, const ParamValues& v)
      : bar_px_(v.integer("bar_px")), native_(make_technique("native", without_params(c))) {}

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    FrameStats s = native_->render(scene, frame, gaze, target);
    const float black[4] = {0, 0, 0, 1};
    gpu::open_write_masks();  // (which turns the scissor off: enable it after)
    glEnable(GL_SCISSOR_TEST);
    for (int y : {0, target.height() - bar_px_}) {
      glScissor(0, y, target.width(), bar_px_);
      glClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, black);
    }
    glDisable(GL_SCISSOR_TEST);
    return s;
  }
  std::vector<OverlayShape> overlay(const GazeState& g) const override {
    return {{OverlayShape::Kind::Dot, g.gaze_px.x, g.gaze_px.y, 4, 4, 1, 1, 1}};
  }

 private:
  static TechniqueConfig without_params(TechniqueConfig c) {
    c.params.clear();
    return c;
  }
  int bar_px_;
  std::unique_ptr<Technique> native_;
};

/// Registers the technique once per process (later calls do nothing).
inline void register_bars_technique() {
  for (const TechniqueInfo& t : techniques()) {
    if (t.name == kBarsTechnique) return;
  }
  TechniqueInfo t;
  t.name = kBarsTechnique;
  t.summary = "native with black bars at the top and bottom (a test of run-time registration)";
  t.source = "foveate's tests";
  t.params = {
      {"bar_px", "height of each bar", "px", ParamType::Integer, 0, 64, 0,
       [](const TechniqueConfig& c, const ParamValues&) { return c.display.height_px / 36.0; }}};
  t.make = construct<BarsTechnique>();
  register_technique(std::move(t));
}

}  // namespace foveate::test
