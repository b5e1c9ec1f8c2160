#include "foveate/techniques/supersampled_native.hpp"

#include <cmath>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "foveate/techniques/technique.hpp"

namespace foveate {

struct SupersampledNative::Impl {
  Display display;
  std::unique_ptr<Technique> native;
  gpu::RenderTarget big, out;
  tech::PassKit kit;
};

SupersampledNative::SupersampledNative(const Display& display, int factor)
    : impl_(std::make_unique<Impl>()), factor_(factor) {
  if (factor < 2 || factor > 8)
    throw Error("supersampling factor " + std::to_string(factor) + ": expected 2..8");
  const int w = display.width_px * factor, h = display.height_px * factor;
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  if (w > max || h > max) {
    throw Error("a " + std::to_string(factor) + "x" + std::to_string(factor) +
                " supersampled reference needs " + std::to_string(w) + "x" + std::to_string(h) +
                " pixels, beyond this GL's limit of " + std::to_string(max) +
                "; use a smaller factor (ssaa:N)");
  }
  impl_->display = display;
  TechniqueConfig c;
  c.display = display.resized(w, h);
  impl_->native = make_technique("native", c);
  impl_->big.ensure(w, h);
  impl_->out.ensure(display.width_px, display.height_px);
}

SupersampledNative::~SupersampledNative() = default;

const gpu::RenderTarget& SupersampledNative::render(Scene& scene, const FrameInput& input) {
  Impl& m = *impl_;
  FrameInput big = input;
  big.width = input.width * factor_;
  big.height = input.height * factor_;
  big.mouse_px = {input.mouse_px.x * factor_, input.mouse_px.y * factor_};
  scene.update(big);
  m.native->render(scene, big, GazeState{}, m.big);
  m.kit.pass(m.kit.fullscreen("runner/resolve_box.frag"), m.out, {},
             [&](const gpu::Program& p, gpu::Samplers& samplers) {
               samplers.bind(p, "u_source", m.big.color());
               p.set("u_factor", factor_);
             });
  return m.out;
}

Image SupersampledNative::read() const { return gpu::read_texture(impl_->out.color()); }

int parse_reference(const std::string& text) {
  if (text == "native") return 1;
  if (text == "ssaa") return 4;
  if (text.rfind("ssaa:", 0) == 0) {
    double n = 0;
    if (parse_number(text.substr(5), n) && n == std::floor(n) && n >= 2 && n <= 8)
      return static_cast<int>(n);
  }
  throw Error("'" + text + "': expected native, ssaa or ssaa:N with N from 2 to 8");
}

}  // namespace foveate
