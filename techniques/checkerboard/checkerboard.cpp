// checkerboard: mask-based foveated rendering as in Silvera, "OpenGL Foveated
// Rendering" (2022), after Wei's MBFR. Pixels form n x n quads in 2 x 2 tiles;
// four regions around the gaze drop 0, 1, 2 and 3 quads of every tile, and
// only the kept pixels are shaded; the split by region is counted on the CPU
// from the same pattern.
//
// Where each region may begin follows from the block size: a region's
// effective sampling is set by the largest gap its pattern leaves between
// kept pixels (n + 1 pixels across the n x n holes of regions 1 and 2,
// (n + 1) sqrt 2 in region 3), and it may begin only where the MAR in pixels
// is at least twice that gap (CheckerboardPattern::from_acuity). Regions 1
// and 2 leave the same gap, so region 1 is empty by default.
//
// With 1-pixel quads (block 1, the default) a stencil mask would save
// nothing (a rasteriser shades whole 2x2 quads, llvmpipe 4x4 blocks), so the pixels
// beyond region 0 are shaded packed: quad q of every tile into a target of its
// own at half the resolution per axis, like a 2x2 shading rate whose samples
// sit on that quad's pixel centres, each drawn over the rectangles of the
// ring where its quad is kept; region 0 is shaded at full resolution over its
// disc. Each pixel is then interpolated from its kept neighbours
// (reconstruct_packed.frag): a kept pixel is its own sample, a dropped one of
// regions 1 and 2 the mean of its four neighbours (all kept there), region 3
// the bilinear interpolation of quad 0's lattice. Without holes wider than a
// pixel to fill, a blur is not needed: on `guenter` and `raymarch` this gives
// both a higher JOD and fewer pixels than 4-pixel quads (docs/fidelity.md).
//
// Larger quads (Silvera's) are rejected by the stencil test before shading,
// which saves their cost where a quad covers the rasteriser's block (4 on
// llvmpipe); one shading pass covers every kept pixel (cheaper than one per
// region: docs/performance.md). Their holes are filled by a normalized
// convolution over the kept samples in linear light (filter.glsl): a
// separable Gaussian of colour times coverage divided by the Gaussian of
// coverage (an explicit mask in alpha, so a black pixel is a valid pixel),
// as wide as a fraction of the region's gap. Kept and
// dropped pixels of regions 1-3 alike come out of it, so no kept quad stands
// out sharp in a blurred field; region 0 is the shaded frame, native. The
// Gaussian is computed at 1/3 resolution by default (the `scale` param) and
// read back bilinearly, and each pixel of the last pass reads only what its
// region needs (native fovea, blend band, filtered rest). The
// Gaussian widens smoothly towards each next region, and between the native
// fovea and the first dropped quads a band is shaded in full and fades from
// native to the filtered image, so that no border shows. The band is as wide
// as a fraction of r1's eccentricity (`blend`, 0.1 by tune's choice): the MAR
// grows in proportion to eccentricity, so a band of fixed width would show as
// a step from sharp to soft where the fovea is large (docs/fidelity.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "../registry/registry.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "foveate/techniques/rect_pass.hpp"

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
      : display_(c.display), block_(v.integer("block")), blend_(v.real("blend")) {
    thresholds_px_ = {v.real("r1"), v.real("r2"), v.real("r3")};
    CheckerboardPattern pat;
    pat.block = block_;
    pat.thresholds_px = thresholds_px_;
    pat.validate();
    for (int k = 0; k < 3; ++k) {
      sigmas_[static_cast<size_t>(k)] = v.real("filter") * checkerboard_gap_px(k + 1, block_);
    }
    // By default the filtering runs at the coarsest scale f (pixels per
    // texel, 2 to 4) at which the narrowest Gaussian still has 0.75 texel of
    // its own after the f x f block average and the bilinear read-back
    // (variances (f^2 - 1) / 12 and f^2 / 6 pixel^2): a narrower one leaves
    // the read-back's f-pixel period visible. The default widths give f = 3.
    scale_ = v.integer("scale");
    if (scale_ == 0) {
      const double narrowest = *std::min_element(sigmas_.begin(), sigmas_.end());
      scale_ = 2;
      for (int f = 4; f > 2 && scale_ == 2; --f) {
        const double rest = narrowest * narrowest - (f * f - 1) / 12.0 - f * f / 6.0;
        if (rest >= 0.75 * 0.75 * f * f) scale_ = f;
      }
    }
  }

  std::array<double, 3> thresholds(const GazeState& g) const {
    std::array<double, 3> t = thresholds_px_;
    const double extra = latency_travel_deg(g);
    for (double& x : t) {
      const double e =
          std::atan(x / display_.eye_distance_px()) * 180.0 / 3.14159265358979 * g.fovea_scale +
          extra;
      if (g.fovea_scale != 1.0 || extra > 0.0) x = display_.radius_px_at(e);
    }
    return t;
  }

  // Where things change at this gaze (pixels from the gaze): the native fovea
  // ends at `fovea`, the blend band follows (`band` wide, every pixel still
  // shaded), and quads are dropped from `pattern` on (the thresholds of the
  // stencil pattern: r1..r3, moved out of the band).
  struct Borders {
    double fovea = 0, band = 0;
    std::array<double, 3> pattern{};
  };
  Borders borders(const GazeState& g) const {
    const auto t = thresholds(g);
    Borders b;
    b.fovea = t[0];
    if (blend_ > 0.0) {
      const double e0 = std::atan(t[0] / display_.eye_distance_px()) * 180.0 / 3.14159265358979;
      b.band = display_.radius_px_at(e0 * (1.0 + blend_)) - t[0];
    }
    for (size_t k = 0; k < 3; ++k) b.pattern[k] = std::max(t[k], t[0] + b.band);
    return b;
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    // The pattern is defined in top-left pixel coordinates (CheckerboardPattern);
    // the shaders flip gl_FragCoord to match.
    const Borders b = borders(gaze);
    const View view = View::full(W, H);
    scene.prepass(view);
    // Packed, the frame is read only where it is shaded (region 0): it
    // needs neither a stencil nor a clear.
    frame_.ensure(W, H, GL_SRGB8_ALPHA8, !packed());
    if (!packed()) frame_.clear(0, 0, 0, 0);  // alpha 0 = not covered; stencil 0 = dropped
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    PixelCount shaded;
    if (packed()) {
      shaded = shade_packed(scene, gaze, b, W, H);
    } else {
      // 1. Stencil mask: 1 where the pattern keeps a pixel, 0 where it drops it.
      kit_.pass(kit_.fullscreen("checkerboard/mask.frag"), frame_, gpu::PassState::stencil_mark(),
                pattern_uniforms(gaze, b, H));
      // 2. Shading where the stencil says so: dropped quads never reach the
      //    shader. The plain shading variant: it has no discard and writes no
      //    depth, so the stencil test runs before it (llvmpipe rejects whole
      //    4x4 blocks) without the early-tests variant, which costs more
      //    (docs/performance.md).
      shaded = kit_.shade(
          scene, view, kMapRect, frame_,
          [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); },
          gpu::PassState::stencil_equal());
    }
    CheckerboardPattern pat;
    pat.block = block_;
    pat.thresholds_px = b.pattern;
    const auto by_region = pat.kept_by_region(W, H, gaze.gaze_px);
    for (int k = 0; k < 4; ++k) {
      stats.parts.push_back(
          {"region " + std::to_string(k) + " (drops " + std::to_string(k) + " of 4)",
           by_region[static_cast<size_t>(k)]});
    }
    if (packed())
      reconstruct_packed(gaze, b, target);
    else
      reconstruct(gaze, b, target);
    stats.shaded_pixels = shaded.read();  // once the last pass is sent (PixelCount)
    // Packed, the passes are drawn over rectangles that reach past the
    // pattern's regions (the pixels the interpolation reads there among
    // them): the parts still add up to what was shaded.
    if (packed()) {
      double kept = 0;
      for (double n : by_region) kept += n;
      stats.parts.push_back({"beyond the regions' borders", stats.shaded_pixels - kept});
    }
    return stats;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    // The native fovea, then where regions 1-3 begin.
    const Borders b = borders(gaze);
    const double radii[4] = {b.fovea, b.pattern[0], b.pattern[1], b.pattern[2]};
    static const char* const kLabels[4] = {
        "native fovea: every pixel shaded inside", "region 1 begins: drops 1 of every 4 quads",
        "region 2 begins: drops 2 of every 4 quads", "region 3 begins: drops 3 of every 4 quads"};
    std::vector<OverlayShape> out;
    for (int k = 0; k < 4; ++k) {
      const auto* c = kRingColours[k];
      out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, radii[k], 0, c[0],
                     c[1], c[2], kLabels[k]});
    }
    out.push_back(gaze_dot(gaze));
    return out;
  }

 private:
  bool packed() const { return block_ == 1; }

  // The quads shaded packed (block 1): 0, 2 and 3. Quad 1 is kept in region
  // 0 only, which the frame holds.
  static constexpr std::array<int, 3> kPackedQuads = {0, 2, 3};

  // A quad's pixel in each 2x2 block of GL pixels: its column is the
  // pattern's, its row is counted from the top (CheckerboardPattern).
  static std::array<int, 2> quad_offset(int quad, int H) {
    return {quad / 2, (H - 1 - quad % 2) % 2};
  }

  // How far beyond a region's radius its tiles' pixel centres reach (1.5
  // sqrt 2 pixels, rounded up), and how far the interpolation's bilinear
  // reads reach beyond a pixel (2 sqrt 2).
  static constexpr double kTileReach = 3.0, kReadReach = 3.0;

  // Region 0 at full resolution and quads 0, 2 and 3 packed (block 1), each
  // over rectangles that hold every pixel it keeps and every texel the
  // reconstruction reads (a tile's region is decided by its nearest point:
  // kTileReach, kReadReach). The slack shades a few pixels more, true
  // samples all; since nothing unshaded is read, the targets need no clear.
  PixelCount shade_packed(Scene& scene, const GazeState& gaze, const Borders& b, int W, int H) {
    const Vec2d g = to_gl(gaze.gaze_px, H);
    const View view = View::full(W, H);
    const std::vector<PixelRect> fovea = disc_rects(g.x, g.y, b.pattern[0] + kTileReach, W, H);
    PixelCount shaded = kit_.shade(
        scene, view, kMapRect, frame_,
        [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, view); }, {}, false,
        &fovea);
    // Where each packed quad is read beyond region 0: quad 0 everywhere,
    // quad 2 in region 1 (out to pattern[1], its own pixels only), quad 3
    // in regions 1 and 2, and the neighbours of their pixels.
    const std::array<double, 3> end = {std::numeric_limits<double>::infinity(),
                                       b.pattern[1] + kTileReach,
                                       b.pattern[2] + kTileReach + kReadReach};
    const int tw = (W + 1) / 2, th = (H + 1) / 2;
    for (size_t i = 0; i < kPackedQuads.size(); ++i) {
      const auto [ox, oy] = quad_offset(kPackedQuads[i], H);
      gpu::RenderTarget& t = quads_[i];
      t.ensure(tw, th, GL_SRGB8_ALPHA8);
      t.color().set_filter(GL_LINEAR, GL_LINEAR);
      t.color().set_wrap(GL_CLAMP_TO_EDGE);
      // Texel (i, j) samples GL pixel (2 i + ox, 2 j + oy): distances halve.
      const std::vector<PixelRect> ring =
          end[i] <= b.pattern[0] + kTileReach
              ? std::vector<PixelRect>{}
              : annulus_rects(0.5 * (g.x - ox + 0.5), 0.5 * (g.y - oy + 0.5),
                              0.5 * (b.pattern[0] - kReadReach - 1.0), 0.5 * end[i], tw, th);
      const View grid{0, 0, double(2 * tw), double(2 * th), tw, th, 1.0};
      View at = grid;
      at.x0 += ox - 0.5, at.x1 += ox - 0.5, at.y0 += oy - 0.5, at.y1 += oy - 0.5;
      // A mesh scene shades from the native G-buffer (filled once), as vrs's
      // coarse classes do; a screen-space scene has none.
      const View shade_view = scene.info().has_meshes ? view : grid;
      if (!scene.info().has_meshes) scene.prepass(grid);
      shaded += kit_.shade(
          scene, shade_view, kMapRect, t,
          [&](const gpu::Program& p, gpu::Samplers&) { set_rect_mapping(p, at); }, {}, false,
          &ring);
    }
    return shaded;
  }

  // The reconstruction with packed quads (reconstruct_packed.frag): region 0
  // is the frame; beyond it each pixel is interpolated from its kept
  // neighbours. Pixels nearer the gaze than region 0's radius all lie in
  // it, and those farther than region 3's radius and a tile's reach all in
  // region 3, which reads quad 0 alone (reconstruct_packed_outer.frag).
  void reconstruct_packed(const GazeState& gaze, const Borders& b,
                          const gpu::RenderTarget& target) {
    const int H = target.height();
    const SetUniforms set_pattern = pattern_uniforms(gaze, b, H);
    const double inner = std::max(0.0, b.pattern[0] - 1.0);
    const double outer = std::max(inner + 1.0, b.pattern[2] + kTileReach);
    kit_.pass_around_disc(
        target, to_gl(gaze.gaze_px, H), inner, outer, "checkerboard/reconstruct_fovea.frag",
        "checkerboard/reconstruct_packed.frag", "checkerboard/reconstruct_packed_outer.frag",
        [&](const gpu::Program& p, gpu::Samplers& samplers) {
          p.allow_missing({"u_block", "u_thresholds", "u_gaze_top_left", "u_height", "u_frame",
                           "u_quad0", "u_quad2", "u_quad3", "u_offset0", "u_offset3"});
          set_pattern(p, samplers);
          samplers.bind(p, "u_frame", frame_.color());
          samplers.bind(p, "u_quad0", quads_[0].color());
          samplers.bind(p, "u_quad2", quads_[1].color());
          samplers.bind(p, "u_quad3", quads_[2].color());
          const auto o0 = quad_offset(0, H), o3 = quad_offset(3, H);
          p.set("u_offset0", float(o0[0]), float(o0[1]));
          p.set("u_offset3", float(o3[0]), float(o3[1]));
        });
  }

  // The uniforms of the stencil pattern at this gaze (mask and filters).
  SetUniforms pattern_uniforms(const GazeState& gaze, const Borders& b, int H) const {
    return [this, gaze, t = b.pattern, H](const gpu::Program& p, gpu::Samplers&) {
      p.set("u_block", block_);
      p.set("u_gaze_top_left", float(gaze.gaze_px.x), float(gaze.gaze_px.y));
      p.set("u_thresholds", float(t[0]), float(t[1]), float(t[2]));
      p.set("u_height", float(H));
    };
  }

  // 3. Reconstruction into the target (filter.glsl): the f x f block
  //    average, the horizontal and the vertical Gaussian at 1/f resolution,
  //    then the division by coverage at full resolution. Outside the screen
  //    there are no samples (a transparent border).
  void reconstruct(const GazeState& gaze, const Borders& b, const gpu::RenderTarget& target) {
    const int W = target.width(), H = target.height();
    const int f = scale_;
    frame_.color().set_wrap(GL_CLAMP_TO_BORDER);
    for (gpu::RenderTarget& r : reduced_) {
      r.ensure((W + f - 1) / f, (H + f - 1) / f, GL_RGBA16F);  // weighted sums: over 8 bits
      r.color().set_wrap(GL_CLAMP_TO_BORDER);
    }
    const SetUniforms set_pattern = pattern_uniforms(gaze, b, H);
    const auto set_filter = [&](const gpu::Program& p, gpu::Samplers& s) {
      p.allow_missing({"u_block", "u_thresholds", "u_sigmas", "u_blend", "u_gaze_top_left",
                       "u_height", "u_frame", "u_filtered", "u_scale"});
      set_pattern(p, s);
      p.set("u_sigmas", float(sigmas_[0]), float(sigmas_[1]), float(sigmas_[2]));
      p.set("u_blend", float(b.fovea), float(b.band));
      p.set("u_scale", float(f));
    };
    // Blocks that no later pass reads (well inside the native fovea) are
    // skipped: the last pass reads a texel and its bilinear neighbour beyond
    // the fovea, the vertical pass 3 sigma and a bilinear pair from those, the
    // horizontal pass as far again.
    const double sigma_max = *std::max_element(sigmas_.begin(), sigmas_.end());
    const double reach = 3.0 * sigma_max + 2.0 * f;
    const auto skip = [&](const gpu::Program& p, double r) {
      p.set("u_skip_radius", float(std::max(0.0, b.fovea - 2.0 * f - r)));
    };
    kit_.pass(kit_.fullscreen("checkerboard/reconstruct_down.frag"), reduced_[0], {},
              [&](const gpu::Program& p, gpu::Samplers& samplers) {
                set_filter(p, samplers);
                samplers.bind(p, "u_frame", frame_.color());
                skip(p, 2.0 * reach);
              });
    const gpu::Program& axis = kit_.fullscreen("checkerboard/reconstruct_h.frag");
    for (int k = 0; k < 2; ++k) {
      kit_.pass(axis, reduced_[static_cast<size_t>(k + 1)], {},
                [&](const gpu::Program& p, gpu::Samplers& samplers) {
                  set_filter(p, samplers);
                  samplers.bind(p, "u_input", reduced_[static_cast<size_t>(k)].color());
                  p.set("u_axis", k == 0 ? 1.0f : 0.0f, k == 0 ? 0.0f : 1.0f);
                  skip(p, (1 - k) * reach);
                });
    }
    const auto set_last = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      set_filter(p, samplers);
      samplers.bind(p, "u_frame", frame_.color());
      samplers.bind(p, "u_filtered", reduced_[2].color());
    };
    // Each pixel runs only what it needs: the native fovea one read of the
    // frame, the blend band both reads, the rest one read of the filtered
    // image (on llvmpipe a shader pays for every fetch it contains).
    kit_.pass_around_disc(target, to_gl(gaze.gaze_px, H), b.fovea, b.fovea + b.band + 1.0,
                          "checkerboard/reconstruct_fovea.frag", "checkerboard/reconstruct.frag",
                          "checkerboard/reconstruct_outer.frag", set_last);
  }

  Display display_;
  int block_;
  double blend_;
  std::array<double, 3> thresholds_px_{};
  std::array<double, 3> sigmas_{};  // reconstruction Gaussian of regions 1..3, pixels
  PassKit kit_;
  gpu::RenderTarget frame_;
  int scale_ = 2;                             // f: pixels per texel of the filtered images
  std::array<gpu::RenderTarget, 3> reduced_;  // block average, horizontal, vertical
  std::array<gpu::RenderTarget, 3> quads_;    // packed quads 0, 2 and 3 (block 1)
};

}  // namespace

TechniqueInfo checkerboard_info() {
  TechniqueInfo t;
  t.name = "checkerboard";
  t.summary =
      "Pixel dropping: four regions drop 0-3 of every 4 pixels (shaded packed, a target per "
      "quad) or quads (stencil-rejected), then the dropped ones are filled from the kept.";
  t.source = "Silvera, OpenGL Foveated Rendering, 2022 (after Wei's mask-based foveated rendering)";
  static const std::array<std::string, 3> keys = {"r1", "r2", "r3"};
  const auto radius = [](size_t k) {
    return [k](const TechniqueConfig& c, const ParamValues& v) {
      const double r = default_pattern(c, v).thresholds_px[k];
      return k == 0 ? r : std::max(r, v.real(keys[k - 1]));
    };
  };
  const std::string rule =
      "; default where the MAR in pixels, w(e) ppd(e), reaches twice the largest gap the region's "
      "pattern leaves between kept pixels: two samples per resolvable cycle across the holes";
  t.params = {
      plan_margin_param(1.0),
      param("block",
            "quad size n (tiles are 2n x 2n): 1 = pixels, shaded packed (a target per quad) and "
            "interpolated from their kept neighbours; from 2 on, quads dropped by the stencil test "
            "(4 matches llvmpipe's 4x4 rejection) and filled by the reconstruction Gaussian",
            "px", ParamType::Integer, 1, 256, 1),
      param("fractions",
            "Silvera's fixed thresholds (10/25/40 % of the diagonal) instead of the acuity model",
            "", ParamType::Boolean, 0, 1, 0),
      {"r1",
       "radius of the native fovea, where region 1 (drop 1 of 4) may begin" + rule +
           " (n + 1 for the n x n holes of regions 1 and 2)",
       "px", ParamType::Real, 0, 1e6, 0, radius(0)},
      {"r2", "radius where region 2 (drop 2 of 4) may begin" + rule + " (n + 1, as region 1)", "px",
       ParamType::Real, 0, 1e6, 0, radius(1)},
      {"r3",
       "radius where region 3 (drop 3 of 4) may begin" + rule +
           " ((n + 1) sqrt 2 across its dropped corner quads)",
       "px", ParamType::Real, 0, 1e6, 0, radius(2)},
      param("filter",
            "width of the reconstruction Gaussian (sigma) as a fraction of the region's largest "
            "gap between kept pixels (quads of 2 pixels and more)",
            "", ParamType::Real, 0.3, 2.0, 0.55),
      param("scale",
            "pixels per texel at which the reconstruction Gaussian is computed (then read back "
            "bilinearly); 0 = the coarsest, up to 4, at which the narrowest Gaussian keeps 0.75 "
            "texel of its own beyond the block average and the read-back (3 with the default "
            "filter), so that the scale's own period does not show (quads of 2 pixels and more)",
            "px", ParamType::Integer, 0, 4, 0),
      tuned(
          param(
              "blend",
              "width of the band beyond r1, shaded in full, over which the image fades from native "
              "to the reconstruction filter (and the filter widens towards each next region), as a "
              "fraction of r1's eccentricity (layered's blend band is 0.2 of e_i); regions 1-3 "
              "begin after it (1-pixel quads interpolate: the band is native)",
              "", ParamType::Real, 0.0, 1.0, 0.1),
          {0.1, 0.2, 0.4}),
  };
  t.resolve_passes = {"reconstruct_down",        "reconstruct_h",     "reconstruct",
                      "reconstruct_fovea",       "reconstruct_outer", "reconstruct_packed",
                      "reconstruct_packed_outer"};
  t.make = construct<Checkerboard>();
  return t;
}

}  // namespace foveate::tech
