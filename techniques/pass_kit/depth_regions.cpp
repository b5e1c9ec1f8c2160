#include "foveate/techniques/depth_regions.hpp"

#include <algorithm>

namespace foveate::tech {

namespace {
constexpr int kSides = 48;  // as in region.vert
}

void DepthRegions::begin(const gpu::RenderTarget& target, int regions) {
  if (!fbo_ || target_.width() != target.width() || target_.height() != target.height()) {
    depth_ = gpu::Renderbuffer::create(GL_DEPTH_COMPONENT24, target.width(), target.height());
    fbo_ = gpu::Framebuffer::create();
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    target_ = gpu::RenderTarget::wrap(fbo_.id(), target.width(), target.height());
    vao_ = gpu::VertexArray::create();
  }
  // Attached on every frame: GL names are reused, so a new target's texture
  // can carry the name of one deleted since (and still attached here).
  fbo_.attach(GL_COLOR_ATTACHMENT0, target.color());
  fbo_.check("depth regions");
  regions_ = regions;
  next_ = 0;
  target_.bind();
  gpu::apply(gpu::PassState{GL_LESS, true});
  const float far = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
}

void DepthRegions::prepare(const gpu::Program& p) {
  p.use();
  p.set("u_viewport", float(target_.width()), float(target_.height()));
  // Region k at depth (k + 1) / (regions + 1): later regions lose the test.
  p.set("u_depth", -1.0f + 2.0f * float(next_ + 1) / float(regions_ + 1));
  ++next_;
  glBindVertexArray(vao_.id());
}

void DepthRegions::disc(const gpu::Program& p, Vec2d centre, double radius, bool inscribed) {
  prepare(p);
  p.set("u_centre", float(centre.x), float(centre.y));
  p.set("u_radius", float(std::max(radius, 1e-3)));
  p.set("u_inscribed", inscribed ? 1 : 0);
  glDrawArrays(GL_TRIANGLES, 0, 3 * kSides);
}

void DepthRegions::rest(const gpu::Program& p) {
  prepare(p);
  p.allow_missing({"u_centre", "u_inscribed"});
  p.set("u_radius", -1.0f);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace foveate::tech
