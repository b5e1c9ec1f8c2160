// logpolar: Meng, Du, Zwicker, Varshney, "Kernel Foveated Rendering" (2018).
// The scene is shaded into a kernel log-polar buffer of (W/sigma) x (H/sigma)
// whose columns follow u = K^-1(log r / L) w with K(x) = x^alpha, then mapped
// back to the screen; two-level antialiasing blurs the result with a Gaussian
// whose screen-space width grows with eccentricity (a fixed footprint in the
// buffer). Mesh scenes are shaded deferred: their G-buffer is rasterised at
// native resolution and the lighting runs in the log-polar buffer.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "../common/kit.hpp"
#include "../common/registry.hpp"

namespace foveate::tech {

namespace {

// The largest sigma for which the buffer samples at least as densely as the
// acuity model requires everywhere on screen, for a given alpha: at distance r
// from the gaze the buffer's pixel spans r L alpha t^(1-1/alpha) sigma / W
// radially and 2 pi r sigma / H around, which must not exceed the sampling
// factor s(e(r)) = max(1, w(e) / w*).
double acuity_sigma(const Display& d, const AcuityModel& a, double alpha) {
  const double W = d.width_px, H = d.height_px;
  const double L = std::log(std::hypot(W, H));
  double best = 16.0;
  const double rmax = std::hypot(W, H);
  for (double r = 2.0; r <= rmax; r *= 1.02) {
    const double t = std::log(r) / L;
    const double e = std::atan(r / d.eye_distance_px()) * 180.0 / std::numbers::pi;
    const double s = std::max(1.0, a.mar_deg(e) / d.sharpness_deg());
    const double radial = r * L * alpha * std::pow(t, 1.0 - 1.0 / alpha) / W;
    const double around = 2.0 * std::numbers::pi * r / H;
    best = std::min(best, s / std::max(radial, around));
  }
  return std::clamp(best, 1.0, 16.0);
}

// The kernel in the user study's range [1, 4] that lets the acuity model
// accept the smallest buffer.
double acuity_alpha(const Display& d, const AcuityModel& a) {
  double best_alpha = 1.0, best_sigma = 0.0;
  for (double al = 1.0; al <= 4.0 + 1e-9; al += 0.25) {
    const double s = acuity_sigma(d, a, al);
    if (s > best_sigma + 1e-9) best_sigma = s, best_alpha = al;
  }
  return best_alpha;
}

class LogPolar final : public Technique {
 public:
  LogPolar(const TechniqueConfig& c, const ParamValues& v)
      : sigma_(v.real("sigma")), alpha_(v.real("alpha")), blur_(v.real("blur")) {
    model_ =
        KernelLogPolar{double(c.display.width_px), double(c.display.height_px), sigma_, alpha_};
    model_.validate();
  }

  FrameStats render(Scene& scene, const FrameInput&, const GazeState& gaze,
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
    // Deferred: a mesh scene's G-buffer at native resolution.
    const View native = View::full(W, H);
    scene.prepass(native);
    buffer_.ensure(bw, bh);
    buffer_.color().set_wrap(GL_CLAMP_TO_EDGE);
    glTextureParameteri(buffer_.color().id(), GL_TEXTURE_WRAP_T,
                        GL_REPEAT);  // the angle wraps around
    buffer_.clear(0, 0, 0, 1);
    const auto set_mapping = [&](const gpu::Program& p) {
      p.set("u_lp_gaze", float(g.x), float(g.y));
      p.set("u_lp_L", L);
      p.set("u_lp_alpha", float(alpha_));
      p.set("u_lp_buffer", float(bw), float(bh));
    };
    // Buffer texels whose screen position lies beyond the screen (plus a margin
    // for filtering) are not shaded.
    const double margin = 0.02 * std::hypot(W, H);
    const double shaded = kit_.shade(scene, native, "logpolar/map_logpolar.glsl", buffer_,
                                     [&](const gpu::Program& p, gpu::Samplers&) {
                                       set_mapping(p);
                                       p.set("u_keep_rect", float(-margin), float(-margin),
                                             float(W + margin), float(H + margin));
                                     });
    // Inverse mapping with the two-level antialiasing blur.
    kit_.pass(kit_.fullscreen("logpolar/inverse.frag"), target, {},
              [&](const gpu::Program& p, gpu::Samplers& samplers) {
                samplers.bind(p, "u_buffer", buffer_.color());
                set_mapping(p);
                p.set("u_blur", float(blur_));
              });
    return one_pass_stats("log-polar buffer", shaded, W, H);
  }

  std::vector<OverlayShape> overlay(const GazeState& gaze) const override {
    // Rings where the buffer's radial pixel reaches 1, 2, 4 and 8 screen pixels.
    std::vector<OverlayShape> out;
    int k = 0;
    for (double r = 2.0; r < 4000 && k < 4; r *= 1.01) {
      const double t = std::log(r) / model_.log_extent();
      const double radial =
          r * model_.log_extent() * alpha_ * std::pow(t, 1.0 - 1.0 / alpha_) / model_.buffer_w();
      if (radial >= std::pow(2.0, k)) {
        const auto* c = kRingColours[k];
        out.push_back(
            {OverlayShape::Kind::Circle, gaze.gaze_px.x, gaze.gaze_px.y, r, 0, c[0], c[1], c[2]});
        ++k;
      }
    }
    out.push_back(gaze_dot(gaze));
    return out;
  }

 protected:
  std::vector<std::pair<std::string, double>> derived() const override {
    return {{"buffer_width", std::round(model_.buffer_w())},
            {"buffer_height", std::round(model_.buffer_h())}};
  }

 private:
  double sigma_, alpha_, blur_;
  KernelLogPolar model_;
  Kit kit_;
  gpu::RenderTarget buffer_;
};

}  // namespace

TechniqueInfo logpolar_info() {
  TechniqueInfo t;
  t.name = "logpolar";
  t.summary =
      "Shading in a kernel log-polar buffer (W/sigma x H/sigma, K(x) = x^alpha), mapped back with "
      "an eccentricity-growing Gaussian (two-level antialiasing).";
  t.source = "Meng, Du, Zwicker, Varshney, Kernel Foveated Rendering, 2018";
  t.params = {
      {"alpha", "kernel exponent, K(x) = x^alpha; default from the acuity model within [1, 4]", "",
       ParamType::Real, 0.25, 8.0, 1.0,
       [](const TechniqueConfig& c, const ParamValues&) {
         return acuity_alpha(c.display, c.acuity);
       }},
      {"sigma", "buffer parameter W / w (1 = native size); default from the acuity model", "",
       ParamType::Real, 1.0, 16.0, 1.8,
       [](const TechniqueConfig& c, const ParamValues& v) {
         return acuity_sigma(c.display, c.acuity, v.real("alpha"));
       }},
      param("blur", "antialiasing Gaussian sigma in buffer texels (0 = off)", "texels",
            ParamType::Real, 0.0, 3.0, 0.6),
  };
  t.make = construct<LogPolar>();
  return t;
}

}  // namespace foveate::tech
