#include "foveate/techniques/overlay_pass.hpp"

#include <algorithm>

#include "foveate/techniques/pass_kit.hpp"

namespace foveate {

struct OverlayPass::Impl {
  tech::PassKit kit;
};

OverlayPass::OverlayPass() : impl_(std::make_unique<Impl>()) {}
OverlayPass::~OverlayPass() = default;

void OverlayPass::draw(const std::vector<OverlayShape>& shapes, const gpu::RenderTarget& target) {
  tech::PassKit& kit = impl_->kit;
  const gpu::Program& p = kit.fullscreen("runner/overlay.frag");
  const int n = static_cast<int>(std::min<size_t>(shapes.size(), 32));
  const int height = target.height();
  std::vector<float> geo(static_cast<size_t>(n) * 4), style(static_cast<size_t>(n) * 4);
  for (int i = 0; i < n; ++i) {
    const OverlayShape& s = shapes[static_cast<size_t>(i)];
    const double y = s.kind == OverlayShape::Kind::Rect ? height - s.y - s.h : height - s.y;
    const float kind = s.kind == OverlayShape::Kind::Circle ? 0.f
                       : s.kind == OverlayShape::Kind::Rect ? 1.f
                                                            : 2.f;
    const size_t k = static_cast<size_t>(i) * 4;
    geo[k] = float(s.x), geo[k + 1] = float(y), geo[k + 2] = float(s.w), geo[k + 3] = float(s.h);
    style[k] = s.r, style[k + 1] = s.g, style[k + 2] = s.b, style[k + 3] = kind;
  }
  p.set("u_count", n);
  if (n > 0) {
    glProgramUniform4fv(p.id(), p.uniform("u_shape[0]"), n, geo.data());
    glProgramUniform4fv(p.id(), p.uniform("u_style[0]"), n, style.data());
  }
  gpu::PassState blend;
  blend.alpha_blend = true;
  kit.pass(p, target, blend);
}

}  // namespace foveate
