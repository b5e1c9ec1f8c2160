// checkerboard: mask-based foveated rendering as in Silvera, "OpenGL Foveated
// Rendering" (2022), after Wei's MBFR. Pixels form n x n quads in 2 x 2 tiles;
// four regions around the gaze drop 0, 1, 2 and 3 quads of every tile. Dropped
// quads are rejected by the stencil test before shading, so their cost is
// really saved; a reconstruction pass fills them from the shaded neighbours
// using an explicit coverage mask (alpha), so a black pixel is a valid pixel.
#include <cmath>
#include <tuple>

#include "../common/kit.hpp"
#include "../common/registry.hpp"

namespace foveate::tech {

namespace {

struct CheckerParams {
  int block = 4;
  bool export_stencil = true;
  bool fractions = false;
  std::array<double, 3> thresholds_px{};
};

CheckerParams derive(const TechniqueConfig& c, Params& p) {
  CheckerParams o;
  o.block = static_cast<int>(p.get("block", 4));
  o.fractions = p.get("fractions", 0) != 0.0;
  o.export_stencil = p.get("export_stencil", 1) != 0.0;
  const CheckerboardPattern pat =
      o.fractions
          ? CheckerboardPattern::from_fractions(o.block, c.display.width_px, c.display.height_px)
          : CheckerboardPattern::from_acuity(o.block, c.display, c.acuity);
  o.thresholds_px[0] = p.get("r1", pat.thresholds_px[0]);
  o.thresholds_px[1] = p.get("r2", std::max(pat.thresholds_px[1], o.thresholds_px[0]));
  o.thresholds_px[2] = p.get("r3", std::max(pat.thresholds_px[2], o.thresholds_px[1]));
  return o;
}

class Checkerboard final : public Technique {
 public:
  explicit Checkerboard(const TechniqueConfig& c) : display_(c.display) {
    std::tie(opt_, values_) = derive_options<CheckerParams>("checkerboard", c, derive);
    CheckerboardPattern pat;
    pat.block = opt_.block;
    pat.thresholds_px = opt_.thresholds_px;
    pat.validate();
    stencil_export_ = opt_.export_stencil && epoxy_has_gl_extension("GL_ARB_shader_stencil_export");
  }
  std::string name() const override { return "checkerboard"; }
  std::vector<std::pair<std::string, double>> parameters() const override { return values_; }

  std::array<double, 3> thresholds(const GazeState& g) const {
    std::array<double, 3> t = opt_.thresholds_px;
    const double extra = latency_margin_deg(g);
    for (double& x : t) {
      const double e =
          std::atan(x / display_.focal_px()) * 180.0 / 3.14159265358979 * g.fovea_scale + extra;
      if (g.fovea_scale != 1.0 || extra > 0.0) x = display_.radius_px_at(e);
    }
    return t;
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    GLuint target) override {
    const int W = frame.width, H = frame.height;
    // The pattern is defined in top-left pixel coordinates (CheckerboardPattern);
    // the shaders flip gl_FragCoord to match.
    const auto t = thresholds(gaze);
    const View view = View::full(W, H);
    scene.prepass(view);
    frame_.ensure(W, H, GL_RGBA8, true);
    frame_.bind_viewport();
    glClearColor(0, 0, 0, 0);  // alpha 0 = not covered
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    // 1. Stencil mask: region k + 1 where a pixel of region k is kept, 0 where dropped.
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    if (stencil_export_) {
      // One pass: the shader exports each pixel's stencil value.
      const gpu::Program& mask = kit_.fullscreen("checkerboard/mask_export.frag");
      set_pattern(mask, gaze, t, H);
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      kit_.draw_fullscreen(mask);
    } else {
      const gpu::Program& mask = kit_.fullscreen("checkerboard/mask.frag");
      set_pattern(mask, gaze, t, H);
      for (int k = 0; k < 4; ++k) {
        glStencilFunc(GL_ALWAYS, k + 1, 0xFF);
        mask.set("u_region", k);
        kit_.draw_fullscreen(mask);
      }
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // 2. Shading where the stencil says so, one pass per region so that each
    //    region's fragments are counted: dropped quads never reach the shader.
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    for (int k = 0; k < 4; ++k) {
      glStencilFunc(GL_EQUAL, k + 1, 0xFF);
      const double n = kit_.shade(
          scene, view, kMapRect, [&](const gpu::Program& p) { set_rect_mapping(p, view); }, true);
      stats.parts.push_back(
          {"region " + std::to_string(k) + " (drops " + std::to_string(k) + " of 4)", n});
      stats.shaded_pixels += n;
    }
    glDisable(GL_STENCIL_TEST);
    // 3. Reconstruction into the target.
    const gpu::Program& rec = kit_.fullscreen("checkerboard/reconstruct.frag");
    frame_.color.bind(Scene::kFirstTechniqueUnit);
    rec.set("u_frame", Scene::kFirstTechniqueUnit);
    rec.set("u_block", opt_.block);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, W, H);
    kit_.draw_fullscreen(rec);
    return stats;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const auto t = thresholds(gaze);
    const float colours[3][3] = {{1, 0.1f, 0.1f}, {0.1f, 0.9f, 0.2f}, {0.2f, 0.4f, 1}};
    std::vector<OverlayShape> out;
    for (int k = 0; k < 3; ++k) {
      out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y,
                     t[static_cast<size_t>(k)], 0, colours[k][0], colours[k][1], colours[k][2]});
    }
    out.push_back(
        {OverlayShape::Kind::Dot, gaze.gaze_px.x, gaze.gaze_px.y, 4, 4, 1.0f, 0.3f, 0.8f});
    return out;
  }

 private:
  void set_pattern(const gpu::Program& p, const GazeState& g, const std::array<double, 3>& t,
                   int H) const {
    p.set("u_block", opt_.block);
    p.set("u_gaze", float(g.gaze_px.x), float(g.gaze_px.y));
    p.set("u_thresholds", float(t[0]), float(t[1]), float(t[2]));
    p.set("u_height", float(H));
  }

  Display display_;
  CheckerParams opt_;
  std::vector<std::pair<std::string, double>> values_;
  Kit kit_;
  Target frame_;
  bool stencil_export_ = false;
};

}  // namespace

TechniqueInfo checkerboard_info() {
  return {
      "checkerboard",
      "Mask-based pixel dropping: four regions drop 0-3 of every 4 quads (stencil-rejected), "
      "then a reconstruction pass fills them.",
      "Silvera, OpenGL Foveated Rendering, 2022 (after Wei's mask-based foveated rendering)",
      {{"block", "quad size n in pixels (tiles are 2n x 2n); 4 matches llvmpipe's 4x4 rejection", 1,
        256, true},
       {"fractions",
        "1 = Silvera's fixed thresholds (10/25/40 % of the diagonal) instead of the acuity model",
        0, 1, true},
       {"export_stencil",
        "write the region mask in one pass with ARB_shader_stencil_export where the driver has "
        "it (0 = four passes)",
        0, 1, true},
       {"r1", "radius (px) where region 1 (drop 1 of 4) begins", 0, 1e6, false},
       {"r2", "radius (px) where region 2 (drop 2 of 4) begins", 0, 1e6, false},
       {"r3", "radius (px) where region 3 (drop 3 of 4) begins", 0, 1e6, false}},
      [](const TechniqueConfig& c) { return std::make_unique<Checkerboard>(c); },
      [](const TechniqueConfig& c) {
        return derive_options<CheckerParams>("checkerboard", c, derive).second;
      }};
}

}  // namespace foveate::tech
