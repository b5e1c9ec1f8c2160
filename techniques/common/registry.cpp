// The one registry of techniques, and the overlay pass they share.
#include "registry.hpp"

#include <algorithm>

#include "foveate/core/error.hpp"
#include "kit.hpp"

namespace foveate {

const std::vector<TechniqueInfo>& techniques() {
  static const std::vector<TechniqueInfo> all = {tech::native_info(),   tech::layered_info(),
                                                 tech::logpolar_info(), tech::checkerboard_info(),
                                                 tech::lodmask_info(),  tech::inset_info()};
  return all;
}

const TechniqueInfo& technique_info(const std::string& name) {
  for (const TechniqueInfo& t : techniques()) {
    if (t.name == name) return t;
  }
  std::string names;
  for (const TechniqueInfo& t : techniques()) names += (names.empty() ? "" : ", ") + t.name;
  throw Error("unknown technique '" + name + "' (known: " + names + ")");
}

std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueConfig& config) {
  config.display.validate();
  return technique_info(name).make(config);
}

std::vector<std::pair<std::string, double>> default_parameters(const std::string& name,
                                                               const TechniqueConfig& config) {
  return technique_info(name).defaults(config);
}

struct OverlayRenderer::Impl {
  tech::Kit kit;
};

OverlayRenderer::OverlayRenderer() : impl_(std::make_unique<Impl>()) {}
OverlayRenderer::~OverlayRenderer() = default;

void OverlayRenderer::draw(const std::vector<OverlayShape>& shapes, int width, int height,
                           GLuint target) {
  tech::Kit& kit = impl_->kit;
  const gpu::Program& p = kit.fullscreen("common/overlay.frag");
  const int n = static_cast<int>(std::min<size_t>(shapes.size(), 32));
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
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, width, height);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  kit.draw_fullscreen(p);
  glDisable(GL_BLEND);
}

}  // namespace foveate
