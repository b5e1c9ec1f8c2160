// marwarp: shading into one buffer whose sampling follows the acuity model
// (issue 30; docs/continuous.md). The buffer is a radial warp around the
// gaze (core/acuity_warp.hpp): its columns are distances from the gaze
// spaced at half the planned MAR (the integral of 2 / w(e) de), its rows
// angles, as many as keep the spacing across the rays within half the MAR
// everywhere on the screen. Inside the eccentricity where that spacing
// reaches one pixel the screen's own pixels are shaded (the native disc),
// fading into the buffer over a band beyond it.
//
//  * Shading: the scene at each texel's screen position (clamped to the
//    screen), over the texels that land on the screen (acuity_warp_cover).
//    Mesh scenes are shaded deferred from native's G-buffer, or from
//    G-buffers at 1, 1/2, 1/4 ... resolution (`gbuffer_levels`), each
//    filled only over the box that its texels reach and read by the texels
//    whose spacing is at least `gbuffer_ratio` of its pixel. The finest
//    level has native's projection, so the native disc is native's pixels
//    exactly.
//  * Antialiasing in the buffer: texels that differ from a neighbour by
//    more than `edge_contrast` are reshaded with `edge_samples` more
//    (PassKit::supersample_edges).
//  * Resolve, in linear light: a sharpening prefilter in the buffer
//    (sharpen.frag) that undoes what the bilinear read of the inverse
//    mapping attenuates below the cutoff, then one bilinear read per screen
//    pixel (on llvmpipe each fetch per output pixel costs 7-10 ms at
//    1080p), split into regions (native disc, blend band, buffer alone).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "../registry/registry.hpp"
#include "foveate/core/acuity_warp.hpp"
#include "foveate/core/error.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

constexpr double kBandFraction = 0.15;  // blend band beyond the native disc, of its radius
constexpr int kPad = 2;                 // texels the prefilter and the bilinear read reach

// The least radius (pixels) at which both spacings of the mapping reach
// `spacing` pixels (both grow with the radius).
double radius_for_spacing(const AcuityWarpMapping& m, double spacing, double far) {
  const auto ok = [&](double r) {
    return m.radial_spacing_px(r) >= spacing && m.tangential_spacing_px(r) >= spacing;
  };
  if (ok(0.0)) return 0.0;
  if (!ok(far)) return far;
  double lo = 0.0, hi = far;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ok(mid) ? hi : lo) = mid;
  }
  return hi;
}

class MarWarp final : public Technique {
 public:
  MarWarp(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        warp_(c.display, c.acuity),
        fovea_deg_(v.real("fovea_deg")),
        sharpen_(v.real("sharpen")),
        samples_(v.integer("samples")),
        edge_(v.real("edge_contrast")),
        edge_samples_(v.integer("edge_samples")),
        levels_(v.integer("gbuffer_levels")),
        ratio_(v.real("gbuffer_ratio")) {
    const Vec2d centre{0.5 * display_.width_px, 0.5 * display_.height_px};
    planned_ = warp_.mapping(centre);
  }

  // Radius (pixels) of the native disc: where the mapping's spacing reaches
  // a pixel, at least fovea_deg, widened by a tracker fallback and grown by
  // the angle the eye travels during the gaze latency.
  double native_px(const AcuityWarpMapping& m, const GazeState& g) const {
    const double e = std::max(m.start_deg, fovea_deg_) * g.fovea_scale + latency_travel_deg(g);
    return std::max(m.start_px(), display_.radius_px_at(e));
  }

  const AcuityWarpMapping& mapping_for(Vec2d gaze_top_left) {
    if (!has_mapping_ || gaze_top_left.x != mapped_gaze_.x || gaze_top_left.y != mapped_gaze_.y) {
      mapping_ = warp_.mapping(gaze_top_left);
      mapped_gaze_ = gaze_top_left;
      has_mapping_ = true;
    }
    return mapping_;
  }

  // One frame's geometry: the mapping at the gaze (in GL's orientation, a
  // mirror image: the same distances and angles), the native disc with its
  // blend band, the buffer's texels that land on the screen.
  struct Frame {
    AcuityWarpMapping m;
    Vec2d g;
    int W = 0, H = 0;
    double r_native = 0, band = 0, far = 0, reach = 0;
    bool has_buffer = false;
    int bw = 0, bh = 0;  // the buffer texture's size (at least the rows + 1)
    std::vector<PixelRect> cover;
    double x0 = 0, y0 = 0;  // the disc's box on the screen
    int fw = 1, fh = 1;
  };

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const Frame f = plan_frame(gaze, target.width(), target.height());
    FrameStats stats;
    stats.native_pixels = double(f.W) * f.H;
    if (f.has_buffer) {
      // Texels left unshaded this frame read as alpha 0 (the prefilter and
      // the edge marks leave them out), never as an earlier frame's.
      buffer_.clear(0, 0, 0, 0);
    }
    // Shading, level by level: level k's G-buffer has pixels of 2^k native
    // ones and shades the texels whose spacing is at least gbuffer_ratio
    // times that (the last level every texel beyond); a scene without
    // geometry shades every texel in one pass.
    const int levels = scene.info().has_meshes ? std::max(levels_, 1) : 1;
    Shaded shaded;
    int first = 0;
    for (int k = 0; k < levels; ++k)
      first = shade_level(scene, f, k, k + 1 == levels, first, shaded);
    resolve(f, target);
    // Read once the frame's last pass is sent (PixelCount).
    const double buffer_px = shaded.buffer.read(), disc_px = shaded.disc.read();
    stats.parts.push_back({"warped buffer", buffer_px});
    stats.parts.push_back({"native disc", disc_px});
    // Each supersampled texel's new samples count as shaded pixels.
    const double edge_px = edge_samples_ * shaded.edges.read();
    stats.parts.push_back({"supersampled edges", edge_px});
    stats.shaded_pixels = buffer_px + disc_px + edge_px;
    return stats;
  }

  Frame plan_frame(const GazeState& gaze, int W, int H) {
    Frame f;
    f.W = W;
    f.H = H;
    f.m = mapping_for(gaze.gaze_px);
    const Vec2d tl{std::clamp(gaze.gaze_px.x, 0.0, double(W)),
                   std::clamp(gaze.gaze_px.y, 0.0, double(H))};
    f.g = to_gl(tl, H);
    f.m.gaze = f.g;
    f.r_native = native_px(f.m, gaze);
    f.band = kBandFraction * f.r_native;
    for (double cx : {0.0, double(W)}) {
      for (double cy : {0.0, double(H)})
        f.far = std::max(f.far, std::hypot(cx - f.g.x, cy - f.g.y));
    }
    // The buffer: as wide as the farthest corner needs and one row more
    // than the mapping has (row `rows` repeats row 0, so that a bilinear
    // read across the angle's wrap finds it there), both grown, never
    // shrunk, as the gaze moves. The rows follow the gaze: sized to them,
    // the buffers (and the edge pass's storage, kept per size) would be
    // reallocated at every change of a saccade.
    f.has_buffer = f.r_native + f.band < f.far;
    const int columns = static_cast<int>(std::ceil(f.m.column(f.far))) + kPad + 1;
    if (f.has_buffer) {
      const int bw = std::max({buffer_.width(), columns, 1});
      const int bh = std::max(buffer_.height(), f.m.rows + 1);
      if (buffer_.width() != bw || buffer_.height() != bh) {
        buffer_.ensure(bw, bh, GL_RGBA16F);
        sharpened_.ensure(bw, bh, GL_RGBA16F);
        for (gpu::RenderTarget* t : {&buffer_, &sharpened_}) t->color().set_wrap(GL_CLAMP_TO_EDGE);
      }
    }
    f.bw = buffer_.width();
    f.bh = buffer_.height();
    // Texels inside this radius are never read (the disc and most of its
    // band show native pixels): not shaded.
    const double skip = std::max(0.0, 0.85 * f.r_native);
    const std::array<double, 4> screen{0.0, 0.0, double(W), double(H)};
    if (f.has_buffer) f.cover = acuity_warp_cover(f.m, f.bw, skip, screen, kPad);

    // The native disc and its blend band, clipped to the screen.
    f.reach = f.r_native + f.band + 1.0;
    f.x0 = std::max(0.0, std::floor(f.g.x - f.reach));
    f.y0 = std::max(0.0, std::floor(f.g.y - f.reach));
    const double x1 = std::min(double(W), std::ceil(f.g.x + f.reach)),
                 y1 = std::min(double(H), std::ceil(f.g.y + f.reach));
    f.fw = std::max(1, static_cast<int>(x1 - f.x0));
    f.fh = std::max(1, static_cast<int>(y1 - f.y0));
    // Its box is clipped to the screen, so its size changes near the edges:
    // the target is grown, never shrunk, and the disc drawn in its corner.
    fovea_.ensure(std::max(fovea_.width(), f.fw), std::max(fovea_.height(), f.fh));
    return f;
  }

  void set_warp(const gpu::Program& p, const Frame& f) const {
    p.set("u_warp_gaze", float(f.g.x), float(f.g.y));
    p.set("u_warp", float(f.m.focal_px), float(f.m.slope), float(f.m.w0_deg),
          float(f.m.slope * f.m.start_deg + f.m.w0_deg));
    p.set("u_warp_buffer", float(f.bw), float(f.m.rows), float(f.bh));
  }

  struct Shaded {
    PixelCount buffer, disc, edges;
  };

  // Shades G-buffer level k: the buffer's columns from `first` to where the
  // level ends, and at level 0 the native disc. Returns the next level's
  // first column.
  int shade_level(Scene& scene, const Frame& f, int k, bool last_level, int first, Shaded& shaded) {
    const int scale = 1 << k;
    const double next_r =
        last_level ? f.far : radius_for_spacing(f.m, ratio_ * double(scale * 2), f.far);
    const int last = last_level ? f.bw : static_cast<int>(std::ceil(f.m.column(next_r)));
    std::vector<PixelRect> level_cover;
    for (const PixelRect& q : f.cover) {
      const int a = std::max(q[0], first), b = std::min(q[2], last);
      if (b > a) level_cover.push_back({a, q[1], b, q[3]});
    }
    const bool shades_disc = k == 0;
    if (level_cover.empty() && !shades_disc) return std::max(first, last);
    const View view = prepass_level(
        scene, f, scale, last_level ? f.far : f.m.radius_at_column(last + 1.0), shades_disc);
    const auto set_shade = [&](const gpu::Program& p, gpu::Samplers&) {
      set_warp(p, f);
      p.set("u_warp_screen", float(f.W), float(f.H));
      if (samples_ > 1) p.set("u_samples", samples_);
    };
    if (!level_cover.empty() && samples_ == 1) {
      shaded.buffer += kit_.shade(scene, view, "marwarp/map_warp.glsl", buffer_, set_shade, {},
                                  false, &level_cover);
    } else if (!level_cover.empty()) {
      // Several samples per texel: each counts as a shaded pixel (the
      // fragments are the texels scene_pass draws, its merged bands).
      kit_.scene_pass(scene, view, kit_.scene_program(scene, "marwarp/shade_samples.frag"), buffer_,
                      {}, set_shade, &level_cover);
      shaded.buffer += PixelCount(samples_ * cover_texels(coarsen_runs(level_cover, 0.08)));
    }
    if (!level_cover.empty() && edge_ > 0.0)
      shaded.edges += kit_.supersample_edges(scene, view, "marwarp/map_warp.glsl", buffer_,
                                             sharpened_.color(), level_cover, first, last, edge_,
                                             set_shade, true, f.m.rows, edge_samples_);
    if (shades_disc) {
      // At the screen's own pixel centres, from native's grid.
      const std::vector<PixelRect> disc_cover =
          disc_rects(f.g.x - f.x0, f.g.y - f.y0, f.reach + 1.0, f.fw, f.fh);
      shaded.disc = kit_.shade(
          scene, view, kMapRect, fovea_,
          [&](const gpu::Program& p, gpu::Samplers&) {
            p.set("u_map_rect", float(f.x0), float(f.y0), float(f.fw), float(f.fh));
            p.set("u_map_target", float(f.fw), float(f.fh));
          },
          {}, false, &disc_cover);
    }
    return std::max(first, last);
  }

  // The level's grid (pixels of `scale` native ones) over the whole screen;
  // a mesh scene's geometry is drawn only in the box its texels reach
  // (`outer` from the gaze; at level 0 at least the native disc).
  View prepass_level(Scene& scene, const Frame& f, int scale, double level_outer,
                     bool shades_disc) {
    const int tw = (f.W + scale - 1) / scale, th = (f.H + scale - 1) / scale;
    const View view{0, 0, double(tw * scale), double(th * scale), tw, th, 1.0};
    if (!scene.info().has_meshes) {
      scene.prepass(view);
      return view;
    }
    const double outer = std::min(f.far, std::max(level_outer, shades_disc ? f.reach : 0.0));
    const int bx0 = std::max(0, static_cast<int>(std::floor((f.g.x - outer) / scale)) - 1);
    const int by0 = std::max(0, static_cast<int>(std::floor((f.g.y - outer) / scale)) - 1);
    const int bx1 = std::min(tw, static_cast<int>(std::ceil((f.g.x + outer) / scale)) + 1);
    const int by1 = std::min(th, static_cast<int>(std::ceil((f.g.y + outer) / scale)) + 1);
    View box = view;
    box.x0 = double(bx0 * scale);
    box.y0 = double(by0 * scale);
    box.x1 = double(bx1 * scale);
    box.y1 = double(by1 * scale);
    gpu::PassState draw;
    draw.scissor = {bx0, by0, bx1 - bx0, by1 - by0};
    scene.prepass_begin(view);
    gpu::apply(draw);
    scene.prepass_draw(box, -1);
    gpu::apply({});
    scene.prepass_end();
    return view;
  }

  // The prefilter over the texels the resolve reads, then the inverse
  // mapping: each pixel reads only what it shows.
  void resolve(const Frame& f, const gpu::RenderTarget& target) {
    const bool sharpen = f.has_buffer && sharpen_ > 0.0 && !f.cover.empty();
    if (sharpen) {
      kit_.rect_pass(kit_.over_rects("marwarp/sharpen.frag"), f.cover, sharpened_, {},
                     [&](const gpu::Program& p, gpu::Samplers& samplers) {
                       samplers.bind(p, "u_buffer", buffer_.color());
                       p.set("u_sharpen", float(sharpen_));
                       p.set("u_rows", f.m.rows);
                     });
    }
    const gpu::RenderTarget& read = sharpen ? sharpened_ : buffer_;
    if (f.has_buffer) {
      // Row `rows` repeats row 0 (warp_uv reads across the wrap there).
      const GLuint id = read.color().id();
      glCopyImageSubData(id, GL_TEXTURE_2D, 0, 0, 0, 0, id, GL_TEXTURE_2D, 0, 0, f.m.rows, 0, f.bw,
                         1, 1);
    }
    const auto set_resolve = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      p.allow_missing({"u_buffer", "u_fovea", "u_fovea_rect", "u_disc", "u_warp_gaze", "u_warp",
                       "u_warp_buffer"});
      // Without a buffer (the disc covers the screen) the disc stands in: never read.
      samplers.bind(p, "u_buffer", f.has_buffer ? read.color() : fovea_.color());
      samplers.bind(p, "u_fovea", fovea_.color());
      p.set("u_fovea_rect", float(f.x0), float(f.y0), float(f.fw), float(f.fh));
      p.set("u_disc", float(f.r_native), float(f.band));
      set_warp(p, f);
    };
    kit_.pass_around_disc(target, f.g, f.r_native, f.reach, "marwarp/resolve_fovea.frag",
                          "marwarp/resolve.frag", "marwarp/resolve_outer.frag", set_resolve);
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    // The native disc, then rings where the buffer's samples lie 2, 4 and 8
    // pixels apart.
    AcuityWarpMapping m = warp_.mapping(gaze.gaze_px);
    std::vector<OverlayShape> out;
    const auto* c0 = kRingColours[0];
    out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, native_px(m, gaze),
                   0, c0[0], c0[1], c0[2], "native disc: native pixels inside"});
    for (int k = 1; k < 4; ++k) {
      const double r = radius_for_spacing(m, std::pow(2.0, k), 1e5);
      const auto* c = kRingColours[k];
      out.push_back(
          {OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, r, 0, c[0], c[1], c[2],
           "warped buffer samples " + std::to_string(1 << k) + " pixels apart from here"});
    }
    out.push_back(gaze_dot(gaze));
    return out;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    // For a gaze at the screen's centre.
    const double W = display_.width_px, H = display_.height_px;
    const double far = std::hypot(0.5 * W, 0.5 * H);
    return {{"buffer_rows", double(planned_.rows)},
            {"buffer_columns", std::ceil(planned_.column(far))},
            {"native_radius_deg", planned_.start_deg},
            {"native_radius_px", planned_.start_px()},
            {"kappa", planned_.kappa}};
  }

 private:
  Display display_;
  AcuityWarp warp_;
  double fovea_deg_, sharpen_;
  int samples_;
  double edge_;
  int edge_samples_;
  int levels_;
  double ratio_;
  AcuityWarpMapping planned_;
  AcuityWarpMapping mapping_;
  Vec2d mapped_gaze_{};
  bool has_mapping_ = false;
  PassKit kit_;
  gpu::RenderTarget buffer_, sharpened_, fovea_;
};

}  // namespace

TechniqueInfo marwarp_info() {
  TechniqueInfo t;
  t.name = "marwarp";
  t.summary =
      "Shading in one radial buffer around the gaze whose sample spacing is half the MAR at every "
      "eccentricity (columns by the integral of 2 / w(e), rows enough across the rays), with "
      "native pixels where that spacing is under a pixel, resolved in linear light by a "
      "prefilter in the buffer and one bilinear read per pixel.";
  t.source = "the acuity model of Guenter et al. 2012, sampled continuously (issue 30)";
  t.params = {
      plan_margin_param(2.0),
      param("fovea_deg",
            "smallest radius of the native disc at the gaze; it always reaches out to where "
            "the buffer's spacing is a pixel",
            "deg", ParamType::Real, 0.0, 30.0, 0.0),
      tuned(param("sharpen",
                  "prefilter in the buffer before the inverse mapping's bilinear read: a kernel "
                  "1 + 4a at the texel, -a at its four neighbours, which lifts the response the "
                  "bilinear read attenuates below the cutoff (0 = no prefilter pass)",
                  "", ParamType::Real, 0.0, 0.5, 0.0),
            {0.0, 0.12, 0.25}),
      // Counts that fill no grid would weight some positions twice.
      listed(
          param(
              "samples",
              "samples per texel, averaged in linear light (a box prefilter over the texel), each "
              "counted as a shaded pixel: 1, 2 or 4 on a rotated grid, or 9 or 16 on a 3x3 or 4x4 "
              "grid, the texel's area average: with edge_contrast=0, what any prefilter could "
              "reach at this spacing (docs/continuous.md)",
              "", ParamType::Integer, 1.0, 16.0, 1.0),
          {1, 2, 4, 9, 16}),
      edge_contrast_param("in the buffer"),
      // Four, not two: with two, guenter at margin 2 falls just beyond the
      // bound in tune's sequence, and margin 2 with four is faster than 2.5
      // with two (docs/fidelity.md).
      edge_samples_param(4.0),
      param("gbuffer_levels",
            "mesh scenes: G-buffers at 1, 1/2, 1/4 ... of native resolution from which the "
            "buffer is shaded, each over the texels that sample at least gbuffer_ratio of its "
            "pixel; default 1 (native's): on llvmpipe each level redraws the geometry, which "
            "costs more than the fill it saves (docs/continuous.md)",
            "", ParamType::Integer, 1.0, 5.0, 1.0),
      param("gbuffer_ratio",
            "mesh scenes: the least ratio of the buffer's sample spacing to the pixel of the "
            "G-buffer it is shaded from",
            "", ParamType::Real, 0.5, 4.0, 2.0),
  };
  t.resolve_passes = {"sharpen", "resolve", "resolve_fovea", "resolve_outer"};
  t.make = construct<MarWarp>();
  return t;
}

}  // namespace foveate::tech
