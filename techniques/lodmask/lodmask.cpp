// lodmask: Knapik and McGowen, "Foveal Rendering" (2016). Three mesh LODs
// (full, about 10 % and 1 % of the triangles); the G-buffer is filled with the
// coarsest LOD, then stencil masks around the gaze let finer LODs overwrite it
// (mid inside the outer circle, full inside the inner one), and lighting is
// deferred. The circles come from the acuity model: the eye resolves half the
// display's detail beyond e where w(e) = 2 w*, a quarter beyond w(e) = 4 w*.
#include <cmath>
#include <tuple>

#include "../common/kit.hpp"
#include "../common/registry.hpp"
#include "foveate/core/error.hpp"

namespace foveate::tech {

namespace {

struct LodParams {
  double inner_deg = 3.0;
  double outer_deg = 6.0;
};

LodParams derive(const TechniqueConfig& c, Params& p) {
  LodParams o;
  const double w = c.display.sharpness_deg();
  o.inner_deg = p.get("inner_deg", std::max(0.5, c.acuity.eccentricity_for_mar(2.0 * w)));
  o.outer_deg = p.get("outer_deg", std::max(o.inner_deg, c.acuity.eccentricity_for_mar(4.0 * w)));
  if (o.outer_deg < o.inner_deg) throw Error("--param outer_deg must be >= inner_deg");
  return o;
}

// Pixel centres (x + 0.5, y + 0.5) of a W x H screen within `r` of `c`, row by row.
double pixels_in_disc(Vec2d c, double r, int W, int H) {
  double n = 0;
  for (int y = 0; y < H; ++y) {
    const double dy = y + 0.5 - c.y;
    if (std::abs(dy) > r) continue;
    const double half = std::sqrt(r * r - dy * dy);
    const double x0 = std::max(0.0, std::ceil(c.x - half - 0.5)),
                 x1 = std::min(double(W) - 1, std::floor(c.x + half - 0.5));
    if (x1 >= x0) n += x1 - x0 + 1;
  }
  return n;
}

class LodMask final : public Technique {
 public:
  explicit LodMask(const TechniqueConfig& c) : display_(c.display) {
    std::tie(opt_, values_) = derive_options<LodParams>("lodmask", c, derive);
  }
  std::string name() const override { return "lodmask"; }
  std::vector<std::pair<std::string, double>> parameters() const override { return values_; }

  std::pair<double, double> radii(const GazeState& g) const {
    const double extra = latency_margin_deg(g);
    return {display_.radius_px_at(opt_.inner_deg * g.fovea_scale + extra),
            display_.radius_px_at(opt_.outer_deg * g.fovea_scale + extra)};
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    GLuint target) override {
    const SceneInfo info = scene.info();
    if (!info.has_mesh_lods) {
      throw Error(
          "technique lodmask changes mesh detail, but scene '" + info.name +
          "' has no meshes (it is shaded in screen space); use a mesh file or the guenter scene");
    }
    const int W = frame.width, H = frame.height;
    const Vec2d g = to_gl(gaze.gaze_px, H);
    const auto [r_in, r_out] = radii(gaze);
    const View view = View::full(W, H);
    scene.prepass_begin(view);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    scene.prepass_draw(view, 2);
    mask(g, r_out, 1);
    glStencilFunc(GL_LEQUAL, 1, 0xFF);  // 1 <= stencil: inside the outer circle
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    scene.prepass_draw(view, 1);
    mask(g, r_in, 2);
    glStencilFunc(GL_EQUAL, 2, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    scene.prepass_draw(view, 0);
    glDisable(GL_STENCIL_TEST);
    scene.prepass_end();
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, W, H);
    const double shaded = kit_.shade(
        scene, view, kMapRect, [&](const gpu::Program& p) { set_rect_mapping(p, view); }, true);
    // Every pixel is lit (deferred); the parts say how many pixels got their
    // geometry from each LOD: pixel centres inside each stencil circle.
    const double in = pixels_in_disc(g, r_in, W, H), out = pixels_in_disc(g, r_out, W, H);
    FrameStats s;
    s.parts = {{"lod 0 (full detail)", in},
               {"lod 1 (about 10 %)", out - in},
               {"lod 2 (about 1 %)", double(W) * H - out}};
    s.shaded_pixels = shaded;
    s.native_pixels = double(W) * H;
    return s;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const auto [r_in, r_out] = radii(gaze);
    return {
        {OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, r_in, 0, 1, 0.1f, 0.1f},
        {OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, r_out, 0, 0.1f, 0.9f, 0.2f},
        {OverlayShape::Kind::Dot, gaze.gaze_px.x, gaze.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f}};
  }

 private:
  // Inside the circle: stencil = value and depth reset to the far plane, so
  // that the finer LOD drawn next replaces the coarser one there.
  void mask(Vec2d g, double radius, int value) {
    const gpu::Program& p = kit_.fullscreen("lodmask/mask.frag");
    p.set("u_centre", float(g.x), float(g.y));
    p.set("u_radius", float(radius));
    GLboolean depth_test = glIsEnabled(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, value, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    kit_.draw_fullscreen(p);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
    if (!depth_test) glDisable(GL_DEPTH_TEST);
  }

  Display display_;
  LodParams opt_;
  std::vector<std::pair<std::string, double>> values_;
  Kit kit_;
};

}  // namespace

TechniqueInfo lodmask_info() {
  return {
      "lodmask",
      "Mesh level of detail per screen region: coarse LOD everywhere, finer LODs inside stencil "
      "circles around the gaze, deferred lighting. Mesh scenes only.",
      "Knapik and McGowen, Foveal Rendering, 2016",
      {{"inner_deg", "radius of the full-detail circle in degrees; default where w(e) = 2 w*", 0.0,
        90.0, false},
       {"outer_deg", "radius of the mid-detail circle in degrees; default where w(e) = 4 w*", 0.0,
        90.0, false}},
      [](const TechniqueConfig& c) { return std::make_unique<LodMask>(c); },
      [](const TechniqueConfig& c) {
        return derive_options<LodParams>("lodmask", c, derive).second;
      }};
}

}  // namespace foveate::tech
