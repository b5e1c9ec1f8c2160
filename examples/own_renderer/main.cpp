// A user's own renderer, foveated. The scene below knows nothing of
// foveation: it says how to shade a screen position (GLSL) and binds its
// uniforms. Any technique then decides which positions get shaded, at what
// rate; foveate::FrameRunner runs the frames and gaze::GazeTracker turns a gaze
// source into the gaze each frame follows. The program also registers a
// technique of its own at run time ("letterbox"), which then runs like the
// built-in ones. Run: ./own_renderer [technique] [out.png]
#include <cstdio>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/core/image.hpp"
#include "foveate/gaze/tracker.hpp"
#include "foveate/gpu/context.hpp"
#include "foveate/techniques/frame_runner.hpp"

namespace {

// An "expensive" procedural pattern: rings around the screen centre.
class RingsScene final : public foveate::Scene {
 public:
  foveate::SceneInfo info() const override {
    return {"rings", "example user scene", false, false, 0};
  }
  std::string shade_key() const override { return "example:rings"; }
  std::vector<foveate::gpu::StageSource::Piece> shade_source() const override {
    return {{"rings.glsl", R"(
uniform vec2 u_size;
uniform float u_time;
vec4 scene_shade(vec2 p) {
  float r = length(p - 0.5 * u_size);
  float v = 0.0;
  for (int i = 1; i <= 64; ++i) v += sin(r * 0.05 * float(i) - u_time) / float(i);
  return vec4(0.5 + 0.5 * v, 0.4, 0.8 - 0.3 * v, 1.0);
})"}};
  }
  void update(const foveate::FrameInput& f) override { frame_ = f; }
  void bind(const foveate::gpu::Program& p, const foveate::View&,
            foveate::gpu::Samplers&) override {
    p.set("u_size", float(frame_.width), float(frame_.height));
    p.set("u_time", float(frame_.time_s));
  }

 private:
  foveate::FrameInput frame_;
};

// A technique of the program's own: layered, with black bars over the top
// and bottom rows.
class Letterbox final : public foveate::Technique {
 public:
  Letterbox(const foveate::TechniqueConfig& c, const foveate::ParamValues& v)
      : bar_px_(v.integer("bar_px")) {
    foveate::TechniqueConfig inner = c;
    inner.params.clear();
    inner_ = foveate::make_technique("layered", inner);
  }
  foveate::FrameStats render(foveate::Scene& scene, const foveate::FrameInput& frame,
                             const foveate::GazeState& gaze,
                             const foveate::gpu::RenderTarget& target) override {
    foveate::FrameStats s = inner_->render(scene, frame, gaze, target);
    const float black[4] = {0, 0, 0, 1};
    foveate::gpu::open_write_masks();
    glEnable(GL_SCISSOR_TEST);
    for (int y : {0, target.height() - bar_px_}) {
      glScissor(0, y, target.width(), bar_px_);
      glClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, black);
    }
    glDisable(GL_SCISSOR_TEST);
    return s;
  }
  std::vector<foveate::OverlayShape> overlay(const foveate::GazeState& g) const override {
    return inner_->overlay(g);
  }

 private:
  int bar_px_;
  std::unique_ptr<foveate::Technique> inner_;
};

void register_letterbox() {
  foveate::TechniqueInfo t;
  t.name = "letterbox";
  t.summary = "layered with cinema bars (an example of a technique registered at run time)";
  t.source = "examples/own_renderer";
  // Declared once: key, help, unit, type, range, and a default derived from
  // the display (an eighth of the height).
  t.params = {{"bar_px", "height of each bar", "px", foveate::ParamType::Integer, 0, 1000, 0,
               [](const foveate::TechniqueConfig& c, const foveate::ParamValues&) {
                 return c.display.height_px / 8.0;
               }}};
  t.make = foveate::construct<Letterbox>();
  foveate::register_technique(std::move(t));
}

}  // namespace

int main(int argc, char** argv) {
  const std::string technique = argc > 1 ? argv[1] : "layered";
  const std::string out = argc > 2 ? argv[2] : "own_renderer.png";
  try {
    register_letterbox();
    auto context = foveate::gpu::create_headless_context();
    // The display's own size: at much less a desktop display's pixels are
    // coarser than the eye resolves, and foveation has nothing to save.
    const int w = 1920, h = 1080;
    foveate::TechniqueConfig config;
    config.display = foveate::Display::load("desktop-1080p").resized(w, h);
    config.acuity = foveate::AcuityModel::preset("A");
    auto t = foveate::make_technique(technique, config);

    RingsScene scene;
    foveate::FrameRunnerOptions options;
    options.width = w;
    options.height = h;
    options.start_time_s = 1.0;
    foveate::FrameRunner runner(scene, options);
    // The gaze: a fixed point here; "trace:FILE", "synthetic:7" or
    // "pupil" work the same way.
    foveate::gaze::GazeContext gc;
    gc.display = config.display;
    foveate::gaze::GazeTracker tracker("600,450", gc);

    foveate::FrameStats stats;
    for (int frame = 0; frame < 3; ++frame) {
      const foveate::GazeState gaze = tracker.at(runner.frame_input(frame).time_s);
      stats = runner.render(*t, frame, gaze);
    }
    foveate::write_png(out, runner.read_output());
    std::printf("%s: shaded %.0f of %.0f pixels (%.1f %%), wrote %s\n", technique.c_str(),
                stats.shaded_pixels, stats.native_pixels,
                100.0 * stats.shaded_pixels / stats.native_pixels, out.c_str());
    return stats.shaded_pixels > 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "own_renderer: %s\n", e.what());
    return 1;
  }
}
