// logpolar: Meng, Du, Zwicker, Varshney, "Kernel Foveated Rendering" (2018).
// The scene is shaded into a kernel log-polar buffer of (W/sigma) x (H/sigma)
// whose columns follow u = K^-1(log r / L) w with K(x) = x^alpha, then mapped
// back to the screen. Mesh scenes are shaded deferred: their G-buffer is
// rasterised at native resolution and the lighting runs in the log-polar
// buffer.
//
// Fidelity:
//  * The fovea is native. Near the gaze the buffer samples the screen more
//    finely than its pixels, and a resampled image there is only a blurred
//    copy of native: within a disc (at least fovea_deg, and out to where the
//    buffer's samples are no closer together than native pixels) the
//    screen's own pixels are shaded and shown, fading into the buffer over a
//    band beyond. Buffer texels inside the disc are not shaded.
//  * No texel shades a position off the screen (where a deferred scene's
//    G-buffer is empty: a dark rim): positions are clamped to the nearest
//    pixel centre, and texels far beyond the screen are not shaded.
//  * alpha and sigma come from the acuity model: for each kernel exponent
//    in the user study's range, the largest sigma whose largest gap between
//    samples (a buffer cell's diagonal, as for the checkerboard's holes) stays
//    within half the MAR in pixels outside the native disc, and of those the
//    alpha that shades the fewest pixels (acuity_kernel). With the fovea
//    native, a kernel above 1 moves buffer columns out of the periphery into
//    the disc, where they are not shaded, but widens the periphery's cells
//    radially: the two balance near 1.25 at 1080p.
//  * Two-level antialiasing (Meng et al.), in linear light: temporal
//    antialiasing in the buffer (jittered samples, reprojected history,
//    neighbourhood clamping; off by default, `temporal` 0: with the edges
//    supersampled, FovVideoVDP against a supersampled reference finds it
//    adds more error than it removes, docs/fidelity.md), then a
//    Gaussian whose width grows from zero
//    at the native disc with eccentricity. Its width depends only on the
//    buffer column, so it is applied in the buffer (blur.frag) and the
//    inverse mapping reads the result once per pixel; the inverse mapping's
//    bilinear read is itself a blur of sigma 0.41 texel, so only a wider
//    Gaussian than that is a pass of its own (the default 0.4 is not).
//  * Antialiasing in the buffer: texels that differ from a neighbour by
//    more than `edge_contrast` are reshaded with `edge_samples` more
//    (PassKit::supersample_edges, as marwarp's): a cell's one sample
//    aliases small objects, highlights and procedural texture and steps
//    silhouettes, which is where FovVideoVDP finds the error.
//  * The inverse mapping is split into regions (native disc, blend band,
//    the rest) so that each pixel reads only what it shows.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <tuple>

#include "../registry/registry.hpp"
#include "foveate/techniques/pass_kit.hpp"
#include "kernel_plan.hpp"

namespace foveate::tech {

namespace logpolar {

namespace {

// Radical inverse in base b: the jitter sequence.
double halton(int i, int b) {
  double f = 1.0, r = 0.0;
  for (int k = i + 1; k > 0; k /= b) {
    f /= b;
    r += f * (k % b);
  }
  return r;
}

class LogPolar final : public Technique {
 public:
  LogPolar(const TechniqueConfig& c, const ParamValues& v)
      : display_(c.display),
        sigma_(v.real("sigma")),
        alpha_(v.real("alpha")),
        blur_(v.real("blur")),
        blur_pass_(needs_blur_pass(blur_)),
        fovea_deg_(v.real("fovea_deg")),
        history_(v.real("temporal")),
        edge_(v.real("edge_contrast")),
        edge_samples_(v.integer("edge_samples")) {
    model_ =
        KernelLogPolar{double(c.display.width_px), double(c.display.height_px), sigma_, alpha_};
    model_.validate();
    plan_ = plan_kernel(display_, c.acuity, fovea_deg_, alpha_, sigma_);
  }

  void reset() override { valid_ = false; }
  // History is made, then reprojected: the steady frame is the third.
  [[nodiscard]] int settle_frames() const override { return 3; }

  // Radius (pixels) of the native disc at this gaze: the planned one, grown
  // by a tracker fallback and the latency travel.
  double native_px(const GazeState& g) const {
    const double e = fovea_deg_ * g.fovea_scale + latency_travel_deg(g);
    return std::max(plan_.native_px, display_.radius_px_at(e));
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    const Mapping m = mapping(gaze, W, H);
    const NativeDisc d = native_disc(m, native_px(gaze), W, H);
    // Deferred: a mesh scene's G-buffer at native resolution.
    const View native = View::full(W, H);
    scene.prepass(native);
    FrameStats stats;
    stats.native_pixels = double(W) * H;
    // Temporal antialiasing needs history that lines up: reprojected through
    // the scene's camera and depth, or an image that holds still. A moving
    // image with neither (Shadertoy scenes) would only get jitter noise and
    // lag (docs/fidelity.md): its buffer is shown as shaded, with no temporal
    // pass.
    if (buffer_.width() != m.buffer_w || buffer_.height() != m.buffer_h) valid_ = false;
    const auto vp = scene.view_projection();
    const std::optional<std::uint64_t> key = scene.image_key();
    const bool still = key && key == last_key_;
    const bool temporal = history_ > 0.0 && (vp.has_value() || still);
    last_key_ = key;
    PixelCount edges;
    const PixelCount shaded = shade_buffer(scene, native, m, d, temporal, frame.frame, edges);
    const PixelCount disc = shade_native_disc(scene, native, d);
    const gpu::RenderTarget& shown = resolve_temporal(scene, native, m, temporal, vp);
    const gpu::RenderTarget& read = blur(shown, m, d);
    inverse(target, m, d, read);
    // Read once the frame's last pass is sent (PixelCount).
    const double buffer_px = shaded.read(), disc_px = disc.read();
    stats.parts.push_back({"log-polar buffer", buffer_px});
    stats.parts.push_back({"native disc", disc_px});
    // Each supersampled texel's new samples count as shaded pixels.
    const double edge_px = edge_samples_ * edges.read();
    if (edge_ > 0.0) stats.parts.push_back({"supersampled edges", edge_px});
    stats.shaded_pixels = buffer_px + disc_px + edge_px;
    return stats;
  }

  // Whether the second level's Gaussian needs a pass of its own: the
  // inverse mapping reads the buffer bilinearly, which blurs by a tent's
  // variance (1/6 texel^2 per axis, sigma 0.41 texel); a Gaussian no wider
  // than that is already there (blur.frag applies only what exceeds it).
  // The 3-tap kernel's variance at the full width, as blur.frag computes it.
  static bool needs_blur_pass(double blur) {
    const double w1 = blur > 0.0 ? std::exp(-0.5 / (blur * blur)) : 0.0;
    return 2.0 * w1 / (1.0 + 2.0 * w1) > 1.0 / 6.0;
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    // The native disc, then rings where the buffer's pixel reaches 2, 4 and 8
    // screen pixels.
    std::vector<OverlayShape> out;
    const auto* c0 = kRingColours[0];
    out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, native_px(gaze), 0,
                   c0[0], c0[1], c0[2], "native disc: native pixels inside"});
    const double L = model_.log_extent();
    int k = 1;
    for (double r = 2.0; r < 4000 && k < 4; r *= 1.01) {
      if (buffer_gap_px(r, L, alpha_, model_.buffer_w(), model_.buffer_h()) >= std::pow(2.0, k)) {
        const auto* c = kRingColours[k];
        out.push_back({OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, r, 0, c[0], c[1],
                       c[2],
                       "log-polar buffer samples " + std::to_string(1 << k) +
                           " screen pixels apart from here"});
        ++k;
      }
    }
    out.push_back(gaze_dot(gaze));
    return out;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    return {{"buffer_width", std::round(model_.buffer_w())},
            {"buffer_height", std::round(model_.buffer_h())},
            {"native_radius_px", plan_.native_px}};
  }

 private:
  /// This frame's log-polar mapping: its centre (GL pixels), L, and the
  /// buffer's size.
  struct Mapping {
    Vec2d gaze;
    float L = 1.0f;
    double far_px = 1.0;  ///< the farthest screen corner from the centre
    int buffer_w = 1, buffer_h = 1;
  };
  /// The native disc and its blend band, and the square of screen pixels
  /// (clipped to the screen) they are shaded into.
  struct NativeDisc {
    Vec2d centre;  ///< GL pixels
    double radius_px = 0, band_px = 0;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    [[nodiscard]] bool on_screen() const { return x1 > x0 && y1 > y0; }
  };

  Mapping mapping(const GazeState& gaze, int W, int H) const {
    Mapping m;
    m.buffer_w = std::max(1, static_cast<int>(std::lround(W / sigma_)));
    m.buffer_h = std::max(1, static_cast<int>(std::lround(H / sigma_)));
    // The log-polar centre must lie on the screen for the buffer to cover it:
    // a gaze off screen is moved to the nearest screen point.
    Vec2d g = to_gl(gaze.gaze_px, H);
    g.x = std::clamp(g.x, 0.0, double(W));
    g.y = std::clamp(g.y, 0.0, double(H));
    m.gaze = g;
    // L spans the screen from the gaze: log of the diagonal (Meng et al.), or
    // of the farthest corner when the gaze is off screen.
    double far = std::hypot(double(W), double(H));
    for (double cx : {0.0, double(W)}) {
      for (double cy : {0.0, double(H)}) far = std::max(far, std::hypot(cx - g.x, cy - g.y));
    }
    m.far_px = far;
    m.L = static_cast<float>(std::log(far));
    return m;
  }

  static NativeDisc native_disc(const Mapping& m, double radius_px, int W, int H) {
    NativeDisc d;
    d.centre = m.gaze;
    d.radius_px = radius_px;
    d.band_px = kBandFraction * radius_px;
    const double reach = radius_px + d.band_px + 1.0;
    d.x0 = std::max(0.0, std::floor(m.gaze.x - reach));
    d.y0 = std::max(0.0, std::floor(m.gaze.y - reach));
    d.x1 = std::min(double(W), std::ceil(m.gaze.x + reach));
    d.y1 = std::min(double(H), std::ceil(m.gaze.y + reach));
    return d;
  }

  void set_mapping(const gpu::Program& p, const Mapping& m) const {
    p.set("u_lp_gaze", float(m.gaze.x), float(m.gaze.y));
    p.set("u_lp_L", m.L);
    p.set("u_lp_alpha", float(alpha_));
    p.set("u_lp_buffer", float(m.buffer_w), float(m.buffer_h));
  }

  // 1. The buffer, jittered by a sub-texel offset per frame (temporal
  //    antialiasing, when `jitter`); alpha 0 where nothing is shaded.
  //    Returns the texels shaded.
  PixelCount shade_buffer(Scene& scene, const View& native, const Mapping& m, const NativeDisc& d,
                          bool jitter, int frame, PixelCount& edges) {
    const int W = native.target_width, H = native.target_height;
    const int bw = m.buffer_w, bh = m.buffer_h;
    buffer_.ensure(bw, bh, GL_SRGB8_ALPHA8);
    buffer_.clear(0, 0, 0, 0);
    const double jx = jitter ? halton(frame, 2) - 0.5 : 0.0;
    const double jy = jitter ? halton(frame, 3) - 0.5 : 0.0;
    // Texels beyond the screen by up to one buffer cell are shaded too (at the
    // nearest pixel), so that a bilinear read at the screen's edge has both of
    // its neighbours: on a tiny or very flat screen (16x2) a cell of the angle
    // axis is wider than the screen, and leaving those texels out showed black.
    const double angle_cell_px = 2.0 * std::numbers::pi * m.far_px / bh;
    const double past_edge_px = std::max(0.02 * std::hypot(W, H), angle_cell_px);
    // The pass is drawn only over the texels that can land outside the
    // skipped disc and inside the kept rectangle (log_polar_cover), most of
    // the buffer at the default plan (docs/performance.md). The mapping has
    // no discard (on llvmpipe a shader that can discard is slower everywhere,
    // and a discarded fragment costs the whole shader), so the few texels the
    // cover's bands take in besides are shaded, at clamped positions.
    const double skip = kSkipFraction * d.radius_px;
    const std::vector<PixelRect> cover =
        log_polar_cover(m.gaze, m.L, alpha_, bw, bh, skip,
                        {-past_edge_px, -past_edge_px, W + past_edge_px, H + past_edge_px});
    const auto set_shade = [&](const gpu::Program& p, gpu::Samplers&) {
      set_mapping(p, m);
      p.set("u_lp_jitter", float(jx), float(jy));
      p.set("u_lp_screen", float(W), float(H));
    };
    PixelCount shaded = kit_.shade(scene, native, "logpolar/map_logpolar.glsl", buffer_, set_shade,
                                   {}, false, &cover);
    // Antialiasing in the buffer: the cells' stair-steps on silhouettes and
    // the small objects and highlights one sample per cell aliases, reshaded
    // with edge_samples more where a texel differs from a neighbour by more
    // than edge_contrast.
    edges = {};
    if (edge_ > 0.0 && !cover.empty()) {
      scratch_.ensure(bw, bh, GL_SRGB8_ALPHA8);
      edges = kit_.supersample_edges(scene, native, "logpolar/map_logpolar.glsl", buffer_,
                                     scratch_.color(), cover, 0, bw, edge_, set_shade, true, 0,
                                     edge_samples_);
    }
    return shaded;
  }

  // 2. The native disc and its blend band, clipped to the screen, shaded
  //    from the same prepass at the screen's own pixel centres.
  PixelCount shade_native_disc(Scene& scene, const View& native, const NativeDisc& d) {
    if (!d.on_screen()) return {};
    const int fw = static_cast<int>(d.x1 - d.x0), fh = static_cast<int>(d.y1 - d.y0);
    fovea_.ensure(fw, fh);
    // Only the disc is read (the square's corners would be 21 % more).
    const double reach = d.radius_px + d.band_px + 1.0;
    const std::vector<PixelRect> disc_cover =
        disc_rects(d.centre.x - d.x0, d.centre.y - d.y0, reach + 1.0, fw, fh);
    return kit_.shade(
        scene, native, kMapRect, fovea_,
        [&](const gpu::Program& p, gpu::Samplers&) {
          p.set("u_map_rect", float(d.x0), float(d.y0), float(fw), float(fh));
          p.set("u_map_target", float(fw), float(fh));
        },
        {}, false, &disc_cover);
  }

  // 3. First level of the antialiasing: temporal, in the buffer. Returns
  //    what the next levels read.
  const gpu::RenderTarget& resolve_temporal(Scene& scene, const View& native, const Mapping& m,
                                            bool temporal,
                                            const std::optional<std::array<float, 16>>& vp) {
    const int bw = m.buffer_w, bh = m.buffer_h;
    const int next = 1 - latest_;
    gpu::RenderTarget& out = history_targets_[static_cast<size_t>(next)];
    out.ensure(bw, bh, GL_RGBA16F);
    const bool blend = temporal && valid_;
    const bool reproject = blend && vp && has_view_proj_;
    const auto set_temporal = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      samplers.bind(p, "u_current", buffer_.color());
      const gpu::Texture& h =
          blend ? history_targets_[static_cast<size_t>(latest_)].color() : buffer_.color();
      samplers.bind(p, "u_history", h);
      set_mapping(p, m);
      p.set("u_lp_screen", float(native.target_width), float(native.target_height));
      p.set("u_prev_mapping", float(prev_gaze_.x), float(prev_gaze_.y), prev_L_);
      p.set("u_history_weight", blend ? float(history_) : 0.0f);
      if (reproject) {
        glProgramUniformMatrix4fv(p.id(), p.uniform("u_prev_view_proj"), 1, GL_FALSE,
                                  prev_view_proj_.data());
      }
    };
    for (gpu::RenderTarget* t : {&buffer_, &history_targets_[0], &history_targets_[1]}) {
      if (t->width() == bw && t->height() == bh) {
        t->color().set_wrap(GL_CLAMP_TO_EDGE);
        glTextureParameteri(t->color().id(), GL_TEXTURE_WRAP_T, GL_REPEAT);  // the angle wraps
      }
    }
    if (reproject) {
      kit_.scene_pass(scene, native, kit_.scene_program(scene, "logpolar/temporal_reproject.frag"),
                      out, {}, set_temporal);
    } else if (temporal) {
      kit_.pass(kit_.fullscreen("logpolar/temporal.frag"), out, {}, set_temporal);
    }
    if (temporal) latest_ = next;
    // Without a temporal pass this frame leaves no history: the next one that
    // has a still image (or a camera to reproject by) starts afresh.
    valid_ = temporal;
    prev_gaze_ = m.gaze;
    prev_L_ = m.L;
    has_view_proj_ = vp.has_value();
    if (vp) prev_view_proj_ = *vp;
    return temporal ? out : buffer_;
  }

  // 4. Second level: the growing Gaussian, in the buffer (blur.frag), where
  //    it is wider than the inverse mapping's bilinear read already is.
  //    Returns what the inverse mapping reads.
  const gpu::RenderTarget& blur(const gpu::RenderTarget& shown, const Mapping& m,
                                const NativeDisc& d) {
    if (!blur_pass_) return shown;
    blurred_.ensure(m.buffer_w, m.buffer_h, GL_RGBA16F);
    blurred_.color().set_wrap(GL_CLAMP_TO_EDGE);
    glTextureParameteri(blurred_.color().id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    kit_.pass(kit_.fullscreen("logpolar/blur.frag"), blurred_, {},
              [&](const gpu::Program& p, gpu::Samplers& samplers) {
                samplers.bind(p, "u_buffer", shown.color());
                p.allow_missing({"u_lp_gaze"});
                set_mapping(p, m);
                p.set("u_disc", float(d.radius_px), float(d.band_px), float(d.radius_px));
                p.set("u_blur", float(blur_));
              });
    return blurred_;
  }

  // 5. Inverse mapping, and the native disc.
  void inverse(const gpu::RenderTarget& target, const Mapping& m, const NativeDisc& d,
               const gpu::RenderTarget& read) {
    const bool has_fovea = d.on_screen();
    const auto set_inverse = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      p.allow_missing({"u_buffer", "u_fovea", "u_fovea_rect", "u_has_fovea", "u_disc", "u_lp_gaze",
                       "u_lp_L", "u_lp_alpha", "u_lp_buffer"});
      samplers.bind(p, "u_buffer", read.color());
      // Without a disc on the screen the buffer stands in (never read).
      samplers.bind(p, "u_fovea", has_fovea ? fovea_.color() : read.color());
      p.set("u_has_fovea", has_fovea ? 1 : 0);
      p.set("u_fovea_rect", float(d.x0), float(d.y0), float(d.x1 - d.x0), float(d.y1 - d.y0));
      p.set("u_disc", float(d.radius_px), float(d.band_px));
      set_mapping(p, m);
    };
    if (!has_fovea) {
      kit_.pass(kit_.fullscreen("logpolar/inverse.frag"), target, {}, set_inverse);
      return;
    }
    // Each pixel runs only what it needs: inside the disc one read of native
    // pixels, in the band both, beyond it one read of the buffer (on llvmpipe
    // a shader pays for every fetch it contains, on both sides of a branch).
    kit_.pass_around_disc(target, m.gaze, d.radius_px, d.radius_px + d.band_px + 1.0,
                          "logpolar/inverse_fovea.frag", "logpolar/inverse.frag",
                          "logpolar/inverse_outer.frag", set_inverse);
  }

  Display display_;
  double sigma_, alpha_, blur_;
  bool blur_pass_;  // the second level's Gaussian is wider than the bilinear read (blur.frag)
  double fovea_deg_, history_, edge_;
  int edge_samples_;
  KernelLogPolar model_;
  KernelPlan plan_;
  PassKit kit_;
  gpu::RenderTarget buffer_, scratch_, fovea_;
  gpu::RenderTarget blurred_;  // the shown buffer with the second level's Gaussian
  std::array<gpu::RenderTarget, 2> history_targets_;
  int latest_ = 0;
  bool valid_ = false;
  std::optional<std::uint64_t> last_key_;
  Vec2d prev_gaze_{};
  float prev_L_ = 1.0f;
  bool has_view_proj_ = false;
  std::array<float, 16> prev_view_proj_{};
};

}  // namespace

}  // namespace logpolar

TechniqueInfo logpolar_info() {
  TechniqueInfo t;
  t.name = "logpolar";
  t.summary =
      "Shading in a kernel log-polar buffer (W/sigma x H/sigma, K(x) = x^alpha) with a native disc "
      "at the gaze, mapped back with two-level antialiasing (temporal in the buffer, a Gaussian "
      "growing with eccentricity).";
  t.source = "Meng, Du, Zwicker, Varshney, Kernel Foveated Rendering, 2018";
  t.params = {
      plan_margin_param(1.5),
      param("fovea_deg",
            "smallest radius of the native disc at the gaze (it also reaches out to where the "
            "buffer's samples are no closer together than native pixels)",
            "deg", ParamType::Real, 0.0, 30.0, 2.5),
      {"alpha",
       "kernel exponent, K(x) = x^alpha; default from the acuity model: of the exponents in "
       "[1, 4], the one whose buffer, at the largest sigma within the MAR outside the native "
       "disc, shades the fewest pixels",
       "", ParamType::Real, 0.25, 8.0, 1.0,
       [](const TechniqueConfig& c, const ParamValues& v) {
         return logpolar::acuity_kernel(c.display, c.acuity, v.real("fovea_deg"));
       }},
      {"sigma",
       "buffer parameter W / w (1 = native size); default the largest whose largest gap between "
       "samples (a cell's diagonal) stays within half the MAR outside the native disc",
       "", ParamType::Real, 1.0, 16.0, 1.8,
       [](const TechniqueConfig& c, const ParamValues& v) {
         return logpolar::plan_kernel(c.display, c.acuity, v.real("fovea_deg"), v.real("alpha"))
             .sigma;
       }},
      tuned(
          param("blur",
                "antialiasing Gaussian sigma in buffer texels, reached one disc radius beyond the "
                "native disc (it grows from 0 there); the inverse mapping's bilinear read blurs by "
                "0.41 by itself, so up to that it costs nothing and adds nothing (0 = the read "
                "alone)",
                "texels", ParamType::Real, 0.0, 3.0, 0.4),
          {0, 0.4, 0.8}),
      tuned(param("temporal",
                  "weight of the reprojected history in the buffer's temporal antialiasing (the "
                  "paper's first level), with sub-texel jitter; 0 = off",
                  "", ParamType::Real, 0.0, 0.95, 0.0),
            {0, 0.5}),
      edge_contrast_param("in the log-polar buffer"),
      // Four, not two: with two, guenter at margin 1.5 falls just beyond the
      // bound in tune's sequence (9.536, native 9.791; docs/fidelity.md).
      edge_samples_param(4.0),
  };
  t.resolve_passes = {"temporal", "temporal_reproject", "blur",
                      "inverse",  "inverse_fovea",      "inverse_outer"};
  t.make = construct<logpolar::LogPolar>();
  return t;
}

}  // namespace foveate::tech
