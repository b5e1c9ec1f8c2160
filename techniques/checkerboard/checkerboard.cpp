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

// The pattern the configuration gives (Silvera's fractions or the acuity model).
CheckerboardPattern default_pattern(const TechniqueConfig& c, const ParamValues& v) {
  const int block = v.integer("block");
  return v.boolean("fractions")
             ? CheckerboardPattern::from_fractions(block, c.display.width_px, c.display.height_px)
             : CheckerboardPattern::from_acuity(block, c.display, c.acuity);
}

class Checkerboard final : public Technique {
 public:
  Checkerboard(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display), block_(v.integer("block")) {
    thresholds_px_ = {v.real("r1"), v.real("r2"), v.real("r3")};
    CheckerboardPattern pat;
    pat.block = block_;
    pat.thresholds_px = thresholds_px_;
    pat.validate();
    stencil_export_ =
        v.boolean("export_stencil") && epoxy_has_gl_extension("GL_ARB_shader_stencil_export");
  }

  std::array<double, 3> thresholds(const GazeState& g) const {
    std::array<double, 3> t = thresholds_px_;
    const double extra = latency_margin_deg(g);
    for (double& x : t) {
      const double e =
          std::atan(x / display_.eye_distance_px()) * 180.0 / 3.14159265358979 * g.fovea_scale +
          extra;
      if (g.fovea_scale != 1.0 || extra > 0.0) x = display_.radius_px_at(e);
    }
    return t;
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    // The pattern is defined in top-left pixel coordinates (CheckerboardPattern);
    // the shaders flip gl_FragCoord to match.
    const auto t = thresholds(gaze);
    const View view = View::full(W, H);
    scene.prepass(view);
    frame_.ensure(W, H, GL_SRGB8_ALPHA8, true);
    frame_.clear(0, 0, 0, 0);  // alpha 0 = not covered; stencil 0 = dropped
    // 1. Stencil mask: region k + 1 where a pixel of region k is kept, 0 where dropped.
    gpu::PassState mask_state;
    mask_state.stencil_func = GL_ALWAYS;
    mask_state.stencil_pass_op = GL_REPLACE;
    mask_state.stencil_write = true;
    mask_state.color_off = true;
    const auto set_pattern = [&](const gpu::Program& p, gpu::Samplers&) {
      p.set("u_block", block_);
      p.set("u_gaze_top_left", float(gaze.gaze_px.x), float(gaze.gaze_px.y));
      p.set("u_thresholds", float(t[0]), float(t[1]), float(t[2]));
      p.set("u_height", float(H));
    };
    if (stencil_export_) {
      // One pass: the shader exports each pixel's stencil value.
      kit_.pass(kit_.fullscreen("checkerboard/mask_export.frag"), frame_, mask_state, set_pattern);
    } else {
      const gpu::Program& mask = kit_.fullscreen("checkerboard/mask.frag");
      for (int k = 0; k < 4; ++k) {
        mask_state.stencil_ref = k + 1;
        kit_.pass(mask, frame_, mask_state, [&](const gpu::Program& p, gpu::Samplers& s) {
          set_pattern(p, s);
          p.set("u_region", k);
        });
      }
    }
    // 2. Shading where the stencil says so, one pass per region so that each
    //    region's fragments are counted: dropped quads never reach the shader.
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    gpu::PassState region;
    region.stencil_func = GL_EQUAL;
    for (int k = 0; k < 4; ++k) {
      region.stencil_ref = k + 1;
      const double n = kit_.shade(
          scene, view, kMapRect, frame_,
          [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); }, region, true);
      stats.parts.push_back(
          {"region " + std::to_string(k) + " (drops " + std::to_string(k) + " of 4)", n});
      stats.shaded_pixels += n;
    }
    // 3. Reconstruction into the target.
    kit_.pass(kit_.fullscreen("checkerboard/reconstruct.frag"), target, {},
              [&](const gpu::Program& p, gpu::Samplers& samplers) {
                samplers.bind(p, "u_frame", frame_.color());
                p.set("u_block", block_);
              });
    return stats;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    const auto t = thresholds(gaze);
    std::vector<OverlayShape> out;
    for (int k = 0; k < 3; ++k) {
      const auto* c = kRingColours[k];
      out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y,
                     t[static_cast<size_t>(k)], 0, c[0], c[1], c[2]});
    }
    out.push_back(gaze_dot(gaze));
    return out;
  }

 private:
  Display display_;
  int block_;
  std::array<double, 3> thresholds_px_{};
  Kit kit_;
  gpu::RenderTarget frame_;
  bool stencil_export_ = false;
};

}  // namespace

TechniqueInfo checkerboard_info() {
  TechniqueInfo t;
  t.name = "checkerboard";
  t.summary =
      "Mask-based pixel dropping: four regions drop 0-3 of every 4 quads (stencil-rejected), then "
      "a reconstruction pass fills them.";
  t.source = "Silvera, OpenGL Foveated Rendering, 2022 (after Wei's mask-based foveated rendering)";
  const auto radius = [](int k) {
    return [k](const TechniqueConfig& c, const ParamValues& v) {
      const double r = default_pattern(c, v).thresholds_px[static_cast<size_t>(k)];
      static const char* const previous[] = {"", "r1", "r2"};
      return k == 0 ? r : std::max(r, v.real(previous[k]));
    };
  };
  t.params = {
      param("block", "quad size n (tiles are 2n x 2n); 4 matches llvmpipe's 4x4 rejection", "px",
            ParamType::Integer, 1, 256, 4),
      param("fractions",
            "Silvera's fixed thresholds (10/25/40 % of the diagonal) instead of the acuity model",
            "", ParamType::Boolean, 0, 1, 0),
      param("export_stencil",
            "write the region mask in one pass with ARB_shader_stencil_export where the driver "
            "has it (0 = four passes)",
            "", ParamType::Boolean, 0, 1, 1),
      {"r1", "radius where region 1 (drop 1 of 4) begins", "px", ParamType::Real, 0, 1e6, 0,
       radius(0)},
      {"r2", "radius where region 2 (drop 2 of 4) begins", "px", ParamType::Real, 0, 1e6, 0,
       radius(1)},
      {"r3", "radius where region 3 (drop 3 of 4) begins", "px", ParamType::Real, 0, 1e6, 0,
       radius(2)},
  };
  t.make = construct<Checkerboard>();
  return t;
}

}  // namespace foveate::tech
