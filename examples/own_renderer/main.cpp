// A user's own renderer, foveated. The scene below knows nothing of
// foveation: it says how to shade a screen position (GLSL) and binds its
// uniforms. Any technique then decides which positions get shaded, at what
// rate. Run: ./own_renderer [technique] [out.png]
#include <cstdio>
#include <string>

#include "foveate/core/image.hpp"
#include "foveate/gpu/context.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/techniques/technique.hpp"

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
  void bind(const foveate::gpu::Program& p, const foveate::View&) override {
    p.set("u_size", float(frame_.width), float(frame_.height));
    p.set("u_time", float(frame_.time_s));
  }

 private:
  foveate::FrameInput frame_;
};

}  // namespace

int main(int argc, char** argv) {
  const std::string technique = argc > 1 ? argv[1] : "layered";
  const std::string out = argc > 2 ? argv[2] : "own_renderer.png";
  try {
    auto context = foveate::gpu::create_headless_context();
    const int w = 640, h = 360;
    foveate::TechniqueConfig config;
    config.display = foveate::Display::load("desktop-1080p").resized(w, h);
    config.acuity = foveate::AcuityModel::quality("A");
    auto t = foveate::make_technique(technique, config);

    auto color = foveate::gpu::Texture::create_2d(GL_RGBA8, w, h);
    auto fbo = foveate::gpu::Framebuffer::create();
    fbo.attach(GL_COLOR_ATTACHMENT0, color);

    RingsScene scene;
    foveate::FrameInput frame;
    frame.width = w;
    frame.height = h;
    frame.time_s = 1.0;
    scene.update(frame);
    const foveate::FrameStats stats =
        t->render(scene, frame, foveate::GazeState{{200, 150}}, fbo.id());
    foveate::write_png(out, foveate::gpu::read_texture(color));
    std::printf("%s: shaded %.0f of %.0f pixels (%.1f %%), wrote %s\n", technique.c_str(),
                stats.shaded_pixels, stats.native_pixels,
                100.0 * stats.shaded_pixels / stats.native_pixels, out.c_str());
    return stats.shaded_pixels > 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "own_renderer: %s\n", e.what());
    return 1;
  }
}
