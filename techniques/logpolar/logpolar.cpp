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
//    neighbourhood clamping; off by default, `temporal` 0, since against a
//    supersampled reference it adds more error than it removes), then a
//    Gaussian whose width grows from zero
//    at the native disc with eccentricity. Its width depends only on the
//    buffer column, so it is applied in the buffer (blur.frag) and the
//    inverse mapping reads the result once per pixel; the inverse mapping's
//    bilinear read is itself a blur of sigma 0.41 texel, so only a wider
//    Gaussian than that is a pass of its own (the default 0.4 is not).
//  * The inverse mapping is split into regions (native disc, blend band,
//    the rest) so that each pixel reads only what it shows.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <tuple>

#include "../common/registry.hpp"
#include "foveate/techniques/pass_kit.hpp"

namespace foveate::tech {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Radical inverse in base b: the jitter sequence.
double halton(int i, int b) {
  double f = 1.0, r = 0.0;
  for (int k = i + 1; k > 0; k /= b) {
    f /= b;
    r += f * (k % b);
  }
  return r;
}

// The largest gap (screen pixels) between the samples of a W x H screen's
// log-polar buffer at distance r from the gaze: the diagonal of its cell,
// which spans r L alpha t^(1 - 1/alpha) / w radially (t = log r / L) and
// 2 pi r / h around; the diameter of the largest disc holding no sample, as
// for the checkerboard's holes (checkerboard_gap_px).
double buffer_gap(double r, double L, double alpha, double w, double h) {
  const double t = std::clamp(std::log(std::max(r, 1.0)) / L, 1e-9, 1.0);
  return std::hypot(r * L * alpha * std::pow(t, 1.0 - 1.0 / alpha) / w,
                    2.0 * std::numbers::pi * r / h);
}

// Native pixels' own largest gap, the diagonal of a pixel.
const double kNativeGap = std::sqrt(2.0);

// The gap the acuity model allows at distance r from a gaze at the display
// centre: half the MAR in pixels (two samples per cycle), and never less than
// native's.
double allowed_gap(const Display& d, const AcuityModel& a, double r) {
  return std::max(kNativeGap, 0.5 * mar_px_at(d, a, std::atan(r / d.eye_distance_px()) * kDeg));
}

// Radius (pixels) of the native disc: at least `min_px`, and out to where the
// buffer's samples are no longer closer together than native pixels.
double native_radius(double min_px, double L, double alpha, double w, double h) {
  double r = 2.0;
  while (r < 1e5 && buffer_gap(r, L, alpha, w, h) < kNativeGap) r *= 1.005;
  return std::max(min_px, r);
}

// What a kernel exponent gives on a display, for a gaze at the centre.
struct KernelPlan {
  double accepted_sigma = 0;  ///< the largest sigma within the MAR outside the disc (unclamped)
  double sigma = 1;           ///< accepted_sigma clamped into [1, 16]
  double native_px = 0;       ///< radius of the native disc
  double shaded = 0;          ///< pixels shaded per frame: buffer texels and the disc's square
};

constexpr double kBandFraction = 0.15;  // blend band beyond the disc, of its radius
constexpr double kSkipFraction = 0.85;  // texels within this much of the radius are not shaded

KernelPlan plan_kernel(const Display& d, const AcuityModel& a, double fovea_deg, double alpha,
                       double sigma = 0.0) {
  const double W = d.width_px, H = d.height_px;
  const double L = std::log(std::hypot(W, H));
  const double min_px = d.radius_px_at(fovea_deg);
  KernelPlan p;
  // The MAR criterion outside the disc, for every distance a gaze anywhere can give.
  double best = 1e9;
  for (double r = min_px; r <= std::hypot(W, H); r *= 1.01) {
    best = std::min(best, allowed_gap(d, a, r) / buffer_gap(r, L, alpha, W, H));
  }
  p.accepted_sigma = best;
  p.sigma = sigma > 0.0 ? sigma : std::clamp(best, 1.0, 16.0);
  const double w = std::max(1.0, std::round(W / p.sigma)),
               h = std::max(1.0, std::round(H / p.sigma));
  p.native_px = native_radius(min_px, L, alpha, w, h);
  // Shaded texels for a gaze at the centre: per row (angle), the columns from
  // the skipped disc out to the screen's edge plus the filtering margin.
  const double skip = kSkipFraction * p.native_px, margin = 0.02 * std::hypot(W, H);
  const auto u = [&](double r) {
    return std::pow(std::clamp(std::log(std::max(r, 1.0)) / L, 0.0, 1.0), 1.0 / alpha) * w;
  };
  for (int j = 0; j < static_cast<int>(h); ++j) {
    const double th = (j + 0.5) / h * 2.0 * std::numbers::pi;
    const double c = std::abs(std::cos(th)), s = std::abs(std::sin(th));
    const double edge = std::min(c > 1e-9 ? 0.5 * W / c : 1e9, s > 1e-9 ? 0.5 * H / s : 1e9);
    p.shaded += std::max(0.0, u(edge + margin) - u(skip));
  }
  const double side = 2.0 * p.native_px * (1.0 + kBandFraction);
  p.shaded += side * side;
  return p;
}

// The kernel exponent in the user study's range [1, 4] (steps of 1/8) whose
// buffer, at the largest sigma the acuity model accepts outside the native
// disc, shades the fewest pixels. Where no buffer is fine enough (sigma would
// be below 1), the most compliant exponents are compared.
double acuity_kernel(const Display& d, const AcuityModel& a, double fovea_deg) {
  double best_alpha = 1.0, best_compliance = -1.0, best_shaded = 0.0;
  for (int i = 0; i <= 24; ++i) {
    const double alpha = 1.0 + i / 8.0;
    const KernelPlan p = plan_kernel(d, a, fovea_deg, alpha);
    const double compliance = std::min(p.accepted_sigma, 1.0);
    if (compliance > best_compliance + 1e-9 ||
        (compliance > best_compliance - 1e-9 && p.shaded < best_shaded)) {
      best_alpha = alpha, best_compliance = compliance, best_shaded = p.shaded;
    }
  }
  return best_alpha;
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
        history_(v.real("temporal")) {
    model_ =
        KernelLogPolar{double(c.display.width_px), double(c.display.height_px), sigma_, alpha_};
    model_.validate();
    plan_ = plan_kernel(display_, c.acuity, fovea_deg_, alpha_, sigma_);
  }

  void reset() override { valid_ = false; }
  // History is made, then reprojected: the steady frame is the third.
  [[nodiscard]] int settle_frames() const override { return 3; }

  // Radius (pixels) of the native disc at this gaze: the planned one, grown
  // by a tracker fallback and the latency margin.
  double native_px(const GazeState& g) const {
    const double e = fovea_deg_ * g.fovea_scale + latency_margin_deg(g);
    return std::max(plan_.native_px, display_.radius_px_at(e));
  }

  FrameStats render(Scene& scene, const FrameInput& frame, const GazeState& gaze,
                    const gpu::RenderTarget& target) override {
    const int W = target.width(), H = target.height();
    const int bw = std::max(1, static_cast<int>(std::lround(W / sigma_)));
    const int bh = std::max(1, static_cast<int>(std::lround(H / sigma_)));
    // The log-polar centre must lie on the screen for the buffer to cover it:
    // a gaze off screen is moved to the nearest screen point.
    Vec2d g = to_gl(gaze.gaze_px, H);
    g.x = std::clamp(g.x, 0.0, double(W));
    g.y = std::clamp(g.y, 0.0, double(H));
    // L spans the screen from the gaze: log of the diagonal (Meng et al.), or
    // of the farthest corner when the gaze is off screen.
    double far = std::hypot(double(W), double(H));
    for (double cx : {0.0, double(W)}) {
      for (double cy : {0.0, double(H)}) far = std::max(far, std::hypot(cx - g.x, cy - g.y));
    }
    const float L = static_cast<float>(std::log(far));
    const double r_native = native_px(gaze);
    const double band = kBandFraction * r_native;
    // Deferred: a mesh scene's G-buffer at native resolution.
    const View native = View::full(W, H);
    scene.prepass(native);
    FrameStats stats;
    stats.native_pixels = double(W) * H;

    // 1. The buffer, jittered by a sub-texel offset per frame (temporal
    //    antialiasing); alpha 0 where nothing is shaded.
    if (buffer_.width() != bw || buffer_.height() != bh) valid_ = false;
    buffer_.ensure(bw, bh);
    buffer_.clear(0, 0, 0, 0);
    // Temporal antialiasing needs history that lines up: reprojected through
    // the scene's camera and depth, or an image that holds still. A moving
    // image with neither (Shadertoy scenes) would only get jitter noise and
    // lag (acuity error 3.56 -> 2.29 codes on raymarch without it): its
    // buffer is shown as shaded, with no temporal pass.
    const auto vp = scene.view_projection();
    const std::optional<std::uint64_t> key = scene.image_key();
    const bool still = key && key == last_key_;
    const bool temporal = history_ > 0.0 && (vp.has_value() || still);
    last_key_ = key;
    const bool jitter = temporal;
    const double jx = jitter ? halton(frame.frame, 2) - 0.5 : 0.0;
    const double jy = jitter ? halton(frame.frame, 3) - 0.5 : 0.0;
    const auto set_mapping = [&](const gpu::Program& p) {
      p.set("u_lp_gaze", float(g.x), float(g.y));
      p.set("u_lp_L", L);
      p.set("u_lp_alpha", float(alpha_));
      p.set("u_lp_buffer", float(bw), float(bh));
    };
    // Texels beyond the screen by up to one buffer cell are shaded too (at the
    // nearest pixel), so that a bilinear read at the screen's edge has both of
    // its neighbours: on a tiny or very flat screen (16x2) a cell of the angle
    // axis is wider than the screen, and leaving those texels out showed black.
    const double angle_cell = 2.0 * std::numbers::pi * far / bh;
    const double margin = std::max(0.02 * std::hypot(W, H), angle_cell);
    // The pass is drawn only over the texels that can land outside the
    // skipped disc and inside the kept rectangle (log_polar_cover): at the
    // default plan the others are 70 % of the buffer. The mapping has no
    // discard (on llvmpipe a shader that can discard is slower everywhere,
    // and a discarded fragment costs the whole shader), so the few texels
    // the cover's bands take in besides are shaded, at clamped positions.
    const double skip = kSkipFraction * r_native;
    const std::vector<PixelRect> cover =
        log_polar_cover(g, L, alpha_, bw, bh, skip, {-margin, -margin, W + margin, H + margin});
    const double shaded = kit_.shade(
        scene, native, "logpolar/map_logpolar.glsl", buffer_,
        [&](const gpu::Program& p, gpu::Samplers&) {
          set_mapping(p);
          p.set("u_lp_jitter", float(jx), float(jy));
          p.set("u_lp_screen", float(W), float(H));
        },
        {}, false, &cover);
    stats.parts.push_back({"log-polar buffer", shaded});

    // 2. The native disc and its blend band, clipped to the screen, shaded
    //    from the same prepass at the screen's own pixel centres.
    const double reach = r_native + band + 1.0;
    const double x0 = std::max(0.0, std::floor(g.x - reach)),
                 y0 = std::max(0.0, std::floor(g.y - reach));
    const double x1 = std::min(double(W), std::ceil(g.x + reach)),
                 y1 = std::min(double(H), std::ceil(g.y + reach));
    const bool has_fovea = x1 > x0 && y1 > y0;
    double disc = 0.0;
    if (has_fovea) {
      const int fw = static_cast<int>(x1 - x0), fh = static_cast<int>(y1 - y0);
      fovea_.ensure(fw, fh);
      // Only the disc is read (the square's corners would be 21 % more).
      const std::vector<PixelRect> disc_cover = disc_rects(g.x - x0, g.y - y0, reach + 1.0, fw, fh);
      disc = kit_.shade(
          scene, native, kMapRect, fovea_,
          [&](const gpu::Program& p, gpu::Samplers&) {
            p.set("u_map_rect", float(x0), float(y0), float(fw), float(fh));
            p.set("u_map_target", float(fw), float(fh));
          },
          {}, false, &disc_cover);
    }
    stats.parts.push_back({"native disc", disc});
    stats.shaded_pixels = shaded + disc;

    // 3. First level of the antialiasing: temporal, in the buffer.
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
      set_mapping(p);
      p.set("u_lp_screen", float(W), float(H));
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
    const gpu::RenderTarget& shown = temporal ? out : buffer_;
    // Without a temporal pass this frame leaves no history: the next one that
    // has a still image (or a camera to reproject by) starts afresh.
    valid_ = temporal;
    prev_gaze_ = g;
    prev_L_ = L;
    has_view_proj_ = vp.has_value();
    if (vp) prev_view_proj_ = *vp;

    // 4. Second level: the growing Gaussian, in the buffer (blur.frag), where
    //    it is wider than the inverse mapping's bilinear read already is.
    const gpu::RenderTarget& read = blur_pass_ ? blurred_ : shown;
    if (blur_pass_) {
      blurred_.ensure(bw, bh, GL_RGBA16F);
      blurred_.color().set_wrap(GL_CLAMP_TO_EDGE);
      glTextureParameteri(blurred_.color().id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
      kit_.pass(kit_.fullscreen("logpolar/blur.frag"), blurred_, {},
                [&](const gpu::Program& p, gpu::Samplers& samplers) {
                  samplers.bind(p, "u_buffer", shown.color());
                  p.allow_missing({"u_lp_gaze"});
                  set_mapping(p);
                  p.set("u_disc", float(r_native), float(band), float(r_native));
                  p.set("u_blur", float(blur_));
                });
    }

    // 5. Inverse mapping, and the native disc.
    const auto set_inverse = [&](const gpu::Program& p, gpu::Samplers& samplers) {
      p.allow_missing({"u_buffer", "u_fovea", "u_fovea_rect", "u_has_fovea", "u_disc", "u_lp_gaze",
                       "u_lp_L", "u_lp_alpha", "u_lp_buffer"});
      samplers.bind(p, "u_buffer", read.color());
      // Without a disc on the screen the buffer stands in (never read).
      samplers.bind(p, "u_fovea", has_fovea ? fovea_.color() : read.color());
      p.set("u_has_fovea", has_fovea ? 1 : 0);
      p.set("u_fovea_rect", float(x0), float(y0), float(x1 - x0), float(y1 - y0));
      p.set("u_disc", float(r_native), float(band));
      set_mapping(p);
    };
    if (!has_fovea) {
      kit_.pass(kit_.fullscreen("logpolar/inverse.frag"), target, {}, set_inverse);
      return stats;
    }
    // Each pixel runs only what it needs: inside the disc one read of native
    // pixels, in the band both, beyond it one read of the buffer (on llvmpipe
    // a shader pays for every fetch it contains, on both sides of a branch).
    kit_.pass_around_disc(target, g, r_native, r_native + band + 1.0, "logpolar/inverse_fovea.frag",
                          "logpolar/inverse.frag", "logpolar/inverse_outer.frag", set_inverse);
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
      if (buffer_gap(r, L, alpha_, model_.buffer_w(), model_.buffer_h()) >= std::pow(2.0, k)) {
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
  Display display_;
  double sigma_, alpha_, blur_;
  bool blur_pass_;  // the second level's Gaussian is wider than the bilinear read (blur.frag)
  double fovea_deg_, history_;
  KernelLogPolar model_;
  KernelPlan plan_;
  PassKit kit_;
  gpu::RenderTarget buffer_, fovea_;
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

TechniqueInfo logpolar_info() {
  TechniqueInfo t;
  t.name = "logpolar";
  t.summary =
      "Shading in a kernel log-polar buffer (W/sigma x H/sigma, K(x) = x^alpha) with a native disc "
      "at the gaze, mapped back with two-level antialiasing (temporal in the buffer, a Gaussian "
      "growing with eccentricity).";
  t.source = "Meng, Du, Zwicker, Varshney, Kernel Foveated Rendering, 2018";
  t.params = {
      plan_margin_param(1.75),
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
         return acuity_kernel(c.display, c.acuity, v.real("fovea_deg"));
       }},
      {"sigma",
       "buffer parameter W / w (1 = native size); default the largest whose largest gap between "
       "samples (a cell's diagonal) stays within half the MAR outside the native disc",
       "", ParamType::Real, 1.0, 16.0, 1.8,
       [](const TechniqueConfig& c, const ParamValues& v) {
         return plan_kernel(c.display, c.acuity, v.real("fovea_deg"), v.real("alpha")).sigma;
       }},
      param("blur",
            "antialiasing Gaussian sigma in buffer texels, reached one disc radius beyond the "
            "native disc (it grows from 0 there); the inverse mapping's bilinear read blurs by "
            "0.41 by itself, so up to that it costs nothing and adds nothing (0 = the read alone)",
            "texels", ParamType::Real, 0.0, 3.0, 0.4),
      param("temporal",
            "weight of the reprojected history in the buffer's temporal antialiasing (the "
            "paper's first level), with sub-texel jitter; 0 = off, the default: against the 4x4 "
            "supersampled reference it adds more acuity error than it removes (docs/fidelity.md)",
            "", ParamType::Real, 0.0, 0.95, 0.0),
  };
  t.resolve_passes = {"temporal", "temporal_reproject", "blur",
                      "inverse",  "inverse_fovea",      "inverse_outer"};
  t.make = construct<LogPolar>();
  return t;
}

}  // namespace foveate::tech
